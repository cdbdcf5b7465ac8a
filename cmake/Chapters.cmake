# How a chapter folder becomes targets.
#
# A chapter folder holds its headers, its .cpp files and main.cpp. Everything but
# main.cpp becomes the object library NN-name-lib, which the program NN-name and
# the reference tests NN-name-tests link. With CGFS_STUDENT_DIR set, the same is
# done with the student's folder of the same name instead of ours, so our tests
# judge the student's code (docs/students.md):
#   - a chapter the student has not started has no targets; its tests are skipped;
#   - a header, main.cpp or options.cpp the student's folder lacks is taken from ours;
#   - a book function the student has not written yet is linked to a stand-in that
#     throws "not written yet: Name" (cmake/NotWrittenYet.cmake), so the tests of
#     what is written run, and the others are reported as not written yet.

# Stops with one line when CGFS_STUDENT_DIR names no folder, or a folder without
# any chapter folder of ours; warns about folders that look like misnamed chapters.
function(cgfs_check_student_dir chapters)
  if(NOT CGFS_STUDENT_DIR)
    return()
  endif()
  string(REPLACE ";" ", " expected "${chapters}")
  if(NOT IS_DIRECTORY "${CGFS_STUDENT_DIR}")
    message(FATAL_ERROR "CGFS_STUDENT_DIR: there is no folder ${CGFS_STUDENT_DIR}")
  endif()
  file(GLOB entries RELATIVE "${CGFS_STUDENT_DIR}" "${CGFS_STUDENT_DIR}/*")
  set(known "")
  set(unknown "")
  foreach(entry IN LISTS entries)
    if(NOT IS_DIRECTORY "${CGFS_STUDENT_DIR}/${entry}")
      continue()
    elseif(entry IN_LIST chapters)
      list(APPEND known "${entry}")
    elseif(entry MATCHES "^[0-9][0-9]")
      list(APPEND unknown "${entry}")
    endif()
  endforeach()
  string(REPLACE ";" ", " unknown "${unknown}")
  if(NOT known)
    if(unknown)
      set(found " (it has ${unknown})")
    endif()
    message(FATAL_ERROR "CGFS_STUDENT_DIR: ${CGFS_STUDENT_DIR} holds no chapter folder${found}; "
      "the folder names are: ${expected}")
  endif()
  if(unknown)
    message(WARNING "CGFS_STUDENT_DIR: ignoring ${unknown}, which is not a chapter folder name; "
      "the folder names are: ${expected}")
  endif()
endfunction()

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

# In a student build, adds to TARGET the stand-ins for every book function that
# the object libraries OBJECT_LIBRARIES call and do not define.
function(cgfs_add_not_written_yet target)
  if(NOT CGFS_STUDENT_DIR)
    return()  # ours: a missing function is a link error, never a skipped test
  endif()
  set(generated "${CMAKE_BINARY_DIR}/not-written-yet/${target}.cpp")
  set(objects "")
  foreach(library IN LISTS ARGN)
    list(APPEND objects "$<TARGET_OBJECTS:${library}>")
  endforeach()
  find_program(CGFS_CXXFILT NAMES c++filt llvm-cxxfilt)  # readable signatures, if there
  add_custom_command(OUTPUT "${generated}"
    COMMAND "${CMAKE_COMMAND}" "-DNM=${CMAKE_NM}" "-DCXXFILT=${CGFS_CXXFILT}" "-DOUTPUT=${generated}"
      "-DOBJECTS=${objects}" -P "${PROJECT_SOURCE_DIR}/cmake/NotWrittenYet.cmake"
    DEPENDS ${objects} "${PROJECT_SOURCE_DIR}/cmake/NotWrittenYet.cmake"
    COMMENT "Finding the book functions ${target} calls that are not written yet"
    VERBATIM)
  target_sources(${target} PRIVATE "${generated}")
  target_link_libraries(${target} PRIVATE cgfs::program)
endfunction()

# Makes TARGET use the headers precompiled once for every chapter of ours.
function(cgfs_reuse_chapter_headers target)
  if(NOT TARGET cgfs_chapter_headers)
    set(source "${CMAKE_BINARY_DIR}/chapter-headers.cpp")
    file(WRITE "${source}" "// Compiles the headers precompiled for every chapter.\n")
    add_library(cgfs_chapter_headers OBJECT "${source}")
    target_link_libraries(cgfs_chapter_headers PRIVATE cgfs::common cgfs::program cgfs_warnings)
    target_precompile_headers(cgfs_chapter_headers PRIVATE
      <algorithm> <array> <cmath> <functional> <memory> <optional> <string> <utility>
      <vector> <glm/glm.hpp> <glm/mat4x4.hpp> <cgfs/canvas.h> <cgfs/color.h> <program/figure.h>
      <cgfs/math.h>)
  endif()
  target_precompile_headers(${target} REUSE_FROM cgfs_chapter_headers)
endfunction()

function(cgfs_add_chapter chapter)
  cgfs_chapter_source_dir(${chapter} dir)
  if(NOT dir)
    message(STATUS "${chapter}: not in ${CGFS_STUDENT_DIR}, its tests will be skipped")
    return()
  endif()

  file(GLOB sources CONFIGURE_DEPENDS "${dir}/*.cpp")
  list(FILTER sources EXCLUDE REGEX "/main\\.cpp$")
  # A student's chapter without options.cpp, the command line's own options (--model,
  # --texture...), which is no book code, takes ours, as it takes main.cpp.
  set(our_options "${PROJECT_SOURCE_DIR}/chapters/${chapter}/options.cpp")
  if(CGFS_STUDENT_DIR AND sources AND NOT EXISTS "${dir}/options.cpp" AND EXISTS "${our_options}")
    list(APPEND sources "${our_options}")
  endif()
  if(NOT sources)
    # A folder with headers only: every function is "not written yet".
    set(sources "${CMAKE_BINARY_DIR}/not-written-yet/${chapter}-nothing.cpp")
    file(WRITE "${sources}" "// ${dir} has no .cpp file yet.\n")
  endif()
  add_library(${chapter}-lib OBJECT ${sources})
  target_include_directories(${chapter}-lib PUBLIC "${dir}")
  if(CGFS_STUDENT_DIR)
    # Headers the student has not copied are copies of ours, in a folder searched
    # after theirs. Copies, not our folder itself: our scenes.h must find their
    # raytracer.h, not the one beside it.
    # A copy is rewritten only when ours changed (configure_file leaves an equal file
    # alone), so that configuring again does not recompile what includes it.
    set(fallback "${CMAKE_BINARY_DIR}/our-headers/${chapter}")
    file(GLOB ours "${PROJECT_SOURCE_DIR}/chapters/${chapter}/*.h")
    file(GLOB theirs CONFIGURE_DEPENDS "${dir}/*.h")  # a new header of theirs reconfigures
    file(GLOB copies "${fallback}/*.h")
    foreach(copy IN LISTS copies)  # a copy of a header they now have, or we no longer
      cmake_path(GET copy FILENAME name)
      if(EXISTS "${dir}/${name}" OR NOT EXISTS "${PROJECT_SOURCE_DIR}/chapters/${chapter}/${name}")
        file(REMOVE "${copy}")
      endif()
    endforeach()
    foreach(header IN LISTS ours)
      cmake_path(GET header FILENAME name)
      if(NOT EXISTS "${dir}/${name}")
        configure_file("${header}" "${fallback}/${name}" COPYONLY)
      endif()
    endforeach()
    target_include_directories(${chapter}-lib PUBLIC "${fallback}")
    # The chapter's include folders, one per line, for scripts/check-student-headers.
    file(GENERATE OUTPUT "${CMAKE_BINARY_DIR}/header-check/${chapter}.flags"
      CONTENT "-I$<JOIN:$<TARGET_PROPERTY:${chapter}-lib,INCLUDE_DIRECTORIES>,\n-I>\n")
  endif()
  target_link_libraries(${chapter}-lib PUBLIC cgfs::common cgfs::program PRIVATE cgfs_warnings)
  if(NOT CGFS_STUDENT_DIR)
    # Ours: a chapter's files are compiled as one unit ("unity build"), and the
    # standard, GLM and common headers every chapter uses are precompiled once for all
    # of them, so the clean build behind scripts/render takes half the time. Every file
    # still includes what it uses. A student's files stay separate units, where two
    # files may each have a helper of the same name, and a missing #include shows.
    set_target_properties(${chapter}-lib PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
    cgfs_reuse_chapter_headers(${chapter}-lib)
  elseif(CGFS_PRECOMPILED_HEADERS)
    # scripts/mistakes, on copies of our chapters, which include what they use: each
    # file still its own unit, the headers precompiled (chapter 15's files compile in
    # 12 s instead of 22).
    cgfs_reuse_chapter_headers(${chapter}-lib)
  endif()

  set(main "${dir}/main.cpp")
  if(NOT EXISTS "${main}")
    set(main "${PROJECT_SOURCE_DIR}/chapters/${chapter}/main.cpp")  # the same in every chapter
  endif()
  add_library(${chapter}-main OBJECT "${main}")
  target_link_libraries(${chapter}-main PRIVATE ${chapter}-lib cgfs_warnings)
  target_compile_definitions(${chapter}-main PRIVATE CGFS_CHAPTER="${chapter}")
  if(NOT CGFS_STUDENT_DIR)
    cgfs_reuse_chapter_headers(${chapter}-main)
  endif()
  add_executable(${chapter} $<TARGET_OBJECTS:${chapter}-main>)
  target_link_libraries(${chapter} PRIVATE ${chapter}-lib)
  cgfs_add_not_written_yet(${chapter} ${chapter}-lib ${chapter}-main)
  set_property(GLOBAL APPEND PROPERTY CGFS_CHAPTER_PROGRAMS ${chapter})
endfunction()

# `render` writes every chapter's figures into out/<chapter>/ (a student build:
# into its own build folder, build-student/out/<chapter>/, never over ours);
# `update-golden` (ours only, never a student's) rewrites tests/golden/<chapter>/.
function(cgfs_add_render_target)
  get_property(programs GLOBAL PROPERTY CGFS_CHAPTER_PROGRAMS)
  if(CGFS_STUDENT_DIR)
    set(out "${CMAKE_BINARY_DIR}/out")
  else()
    set(out "${PROJECT_SOURCE_DIR}/out")
  endif()
  # One target per chapter, render-NN-name, so that a chapter renders as soon as its
  # program is linked, while the others still compile; `render` is all of them, and
  # cgfs-compare, which the same clean build then makes alongside.
  add_custom_target(render)
  # `chapters`: every chapter program, nothing else (scripts/deep-checks, debug build).
  add_custom_target(chapters)
  add_dependencies(chapters ${programs})
  if(NOT CGFS_STUDENT_DIR)
    add_dependencies(render cgfs-compare)  # students use ours (tools/CMakeLists.txt)
  endif()
  set(golden_commands "")
  foreach(program IN LISTS programs)
    add_custom_target(render-${program}
      COMMAND ${program} --output "${out}/${program}"
      WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
      COMMENT "Rendering ${program}'s figures into ${out}/${program}/"
      VERBATIM)
    add_dependencies(render render-${program})
    list(APPEND golden_commands
      COMMAND ${program} --output "${PROJECT_SOURCE_DIR}/tests/golden/${program}")
  endforeach()
  if(NOT CGFS_STUDENT_DIR)
    add_custom_target(update-golden ${golden_commands}
      WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}"
      COMMENT "Rewriting the golden images in tests/golden/ (look at every changed one)"
      VERBATIM USES_TERMINAL)
  endif()
endfunction()
