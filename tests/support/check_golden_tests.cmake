# cmake -DPROGRAM=NN-name -DTESTS=NN-name-tests -DGOLDEN=tests/golden/NN-name -P check_golden_tests.cmake
#
# One golden test per figure: the chapter's figures (PROGRAM --list), its golden
# images (GOLDEN/*.png) and its tests named "<figure> matches its golden image"
# (TESTS --list-test-names-only) are the same names. So a new figure cannot go
# unchecked, and a count of failed golden tests is a count of failed figures. And no
# test's name holds a ';'.
cmake_minimum_required(VERSION 3.22)
execute_process(COMMAND "${PROGRAM}" --list OUTPUT_VARIABLE listing RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --list failed")
endif()
string(REGEX MATCHALL "(^|\n)[^ \n]+" figures "${listing}")
list(TRANSFORM figures STRIP)

get_filename_component(GOLDEN "${GOLDEN}" ABSOLUTE)
file(GLOB images RELATIVE "${GOLDEN}" "${GOLDEN}/*.png")
list(TRANSFORM images REPLACE "\\.png$" "")

execute_process(COMMAND "${TESTS}" --list-test-names-only "[golden]"
  OUTPUT_VARIABLE names RESULT_VARIABLE status)
string(REGEX MATCHALL "[^\n]+ matches its golden image" tests "${names}")
list(TRANSFORM tests REPLACE " matches its golden image$" "")

# A student build makes a ctest test of each test case, and ctest cuts a name at a ';'
# (a list separator to CMake): the cut name would match no test case.
# (Shown as <semicolon>: CMake would split the name there too.)
execute_process(COMMAND "${TESTS}" --list-test-names-only OUTPUT_VARIABLE all_names)
string(REPLACE ";" "<semicolon>" all_names "${all_names}")
string(REGEX MATCHALL "[^\n]*<semicolon>[^\n]*" cut_names "${all_names}")

set(problems "")
foreach(name IN LISTS cut_names)
  string(APPEND problems "\n  a test name with a ';', which ctest would cut: ${name}")
endforeach()
foreach(figure IN LISTS figures)
  if(NOT figure IN_LIST images)
    string(APPEND problems "\n  ${figure}: a figure without a golden image (${GOLDEN}/${figure}.png)")
  endif()
  if(NOT figure IN_LIST tests)
    string(APPEND problems "\n  ${figure}: a figure without a test \"${figure} matches its golden image\"")
  endif()
endforeach()
foreach(name IN LISTS images tests)
  if(NOT name IN_LIST figures)
    string(APPEND problems "\n  ${name}: a golden image or test of no figure of ${PROGRAM}")
  endif()
endforeach()
list(LENGTH figures count)
if(problems)
  message(FATAL_ERROR "figures, golden images and golden tests differ:${problems}")
endif()
message(STATUS "${count} figures, each with its golden image and its own test")
