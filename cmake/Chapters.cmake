# How a chapter folder becomes targets.
#
# A chapter folder holds its headers, its .cpp files and main.cpp. Everything but
# main.cpp becomes the library NN-name-lib, which the program NN-name and the
# reference tests NN-name-tests link. With CGFS_STUDENT_DIR set, the same is done
# with the student's folder of the same name instead of ours, so our tests judge
# the student's code; a chapter the student has not written yet has no targets
# and its tests are reported as skipped.

function(cgfs_chapter_source_dir chapter out_var)
  if(CGFS_STUDENT_DIR)
    set(dir "${CGFS_STUDENT_DIR}/${chapter}")
  else()
    set(dir "${PROJECT_SOURCE_DIR}/chapters/${chapter}")
  endif()
  if(IS_DIRECTORY "${dir}")
    set(${out_var} "${dir}" PARENT_SCOPE)
  else()
    set(${out_var} "" PARENT_SCOPE)
  endif()
endfunction()

function(cgfs_add_chapter chapter)
  cgfs_chapter_source_dir(${chapter} dir)
  if(NOT dir)
    message(STATUS "${chapter}: not in ${CGFS_STUDENT_DIR}, its tests will be skipped")
    return()
  endif()

  file(GLOB sources CONFIGURE_DEPENDS "${dir}/*.cpp")
  list(FILTER sources EXCLUDE REGEX "/main\\.cpp$")
  add_library(${chapter}-lib STATIC ${sources})
  target_include_directories(${chapter}-lib PUBLIC "${dir}")
  target_link_libraries(${chapter}-lib PUBLIC cgfs::common PRIVATE cgfs_warnings)

  if(EXISTS "${dir}/main.cpp")
    add_executable(${chapter} "${dir}/main.cpp")
    target_link_libraries(${chapter} PRIVATE ${chapter}-lib cgfs_warnings)
    target_compile_definitions(${chapter} PRIVATE CGFS_CHAPTER="${chapter}")
    set_property(GLOBAL APPEND PROPERTY CGFS_CHAPTER_PROGRAMS ${chapter})
  endif()
endfunction()

# `render` writes every chapter's figures into out/<chapter>/;
# `update-golden` (ours only, never a student's) rewrites tests/golden/<chapter>/.
function(cgfs_add_render_target)
  get_property(programs GLOBAL PROPERTY CGFS_CHAPTER_PROGRAMS)
  set(render_commands "")
  set(golden_commands "")
  foreach(program IN LISTS programs)
    list(APPEND render_commands
      COMMAND ${program} --output "${PROJECT_SOURCE_DIR}/out/${program}")
    list(APPEND golden_commands
      COMMAND ${program} --output "${PROJECT_SOURCE_DIR}/tests/golden/${program}")
  endforeach()
  add_custom_target(render ${render_commands}
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
    COMMENT "Rendering every chapter's figures into out/"
    VERBATIM USES_TERMINAL)
  if(NOT CGFS_STUDENT_DIR)
    add_custom_target(update-golden ${golden_commands}
      WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
      COMMENT "Rewriting the golden images in tests/golden/ (look at every changed one)"
      VERBATIM USES_TERMINAL)
  endif()
endfunction()
