# Registers a GoogleTest executable's tests with ctest a test suite at a time instead of a test at a
# time: run with `cmake -P` after each build of the executable (getme_add_test, tests/CMakeLists.txt).
# The sanitizer builds use it. There one test process costs about 0.1-0.15 s before and after the
# test itself (the sanitizer runtime's start, LeakSanitizer's scan at exit): getme_mesh_tests' 67
# tests took 11.6 s as 67 processes and 1.4 s as one (docs/development.md, CI).
#
# Input variables:
#   TEST_TARGET       the executable's target name; the list of registered names is TEST_TARGET_TESTS,
#                     as gtest_discover_tests names it, so label scripts can walk it
#   TEST_EXECUTABLE   the executable
#   TEST_WORKING_DIR  the tests' working directory
#   SLOW_REGEX        tests (Suite.Test) matching it are registered one by one, so the `slow` label
#                     can leave exactly them out; empty for none
#   GROUP_SIZE        at most this many tests share a process, so ctest can still spread a long
#                     suite over its jobs
#   CTEST_FILE        the ctest script to write
cmake_minimum_required(VERSION 3.25)

foreach(variable TEST_TARGET TEST_EXECUTABLE TEST_WORKING_DIR GROUP_SIZE CTEST_FILE)
  if(NOT DEFINED ${variable} OR "${${variable}}" STREQUAL "")
    message(FATAL_ERROR "suite_tests.cmake: ${variable} is not set")
  endif()
endforeach()

execute_process(
  COMMAND "${TEST_EXECUTABLE}" --gtest_list_tests
  WORKING_DIRECTORY "${TEST_WORKING_DIR}"
  OUTPUT_VARIABLE listing
  ERROR_VARIABLE listing_errors
  RESULT_VARIABLE listing_result
  TIMEOUT 60)
if(NOT listing_result EQUAL 0)
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests exited with '${listing_result}':\n"
    "${listing}${listing_errors}")
endif()

# The listing: "Suite.  # TypeParam = ..." lines, each followed by "  Test  # GetParam() = ..." lines.
# Other lines (gtest_main's greeting) are neither.
string(REPLACE ";" "\\;" listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(suites "")
set(suite "")
foreach(line IN LISTS lines)
  string(REGEX REPLACE "#.*$" "" line "${line}")
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.[ \t]*$")
    set(suite "${CMAKE_MATCH_1}")
    list(APPEND suites "${suite}")
    set(tests_of_${suite} "")
  elseif(line MATCHES "^  ([A-Za-z0-9_/]+)[ \t]*$" AND NOT suite STREQUAL "")
    list(APPEND "tests_of_${suite}" "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(suites STREQUAL "")
  message(FATAL_ERROR "${TEST_EXECUTABLE} --gtest_list_tests listed no test:\n${listing}")
endif()

# One add_test per group; a skipped test shows in the group's output, but the group counts as run
# (a skip pattern would also hide the failures of the group's other tests).
set(script "# Written by tests/cmake/suite_tests.cmake from ${TEST_EXECUTABLE} --gtest_list_tests\n")
set(registered "")
macro(register name filter)
  string(APPEND script "add_test([==[${name}]==] [==[${TEST_EXECUTABLE}]==] "
    "[==[--gtest_filter=${filter}]==])\n"
    "set_tests_properties([==[${name}]==] PROPERTIES WORKING_DIRECTORY [==[${TEST_WORKING_DIR}]==])\n")
  list(APPEND registered "${name}")
endmacro()

foreach(suite IN LISTS suites)
  set(grouped "")
  set(slow "")
  foreach(test IN LISTS tests_of_${suite})
    if(NOT SLOW_REGEX STREQUAL "" AND "${suite}.${test}" MATCHES "${SLOW_REGEX}")
      list(APPEND slow "${suite}.${test}")
    else()
      list(APPEND grouped "${suite}.${test}")
    endif()
  endforeach()
  list(LENGTH grouped grouped_count)
  list(LENGTH tests_of_${suite} test_count)
  if(grouped_count GREATER 0 AND grouped_count EQUAL test_count AND
     NOT grouped_count GREATER GROUP_SIZE)
    register("${suite}.*" "${suite}.*")
  elseif(grouped_count GREATER 0)
    math(EXPR group_count "(${grouped_count} + ${GROUP_SIZE} - 1) / ${GROUP_SIZE}")
    math(EXPR last_group "${group_count} - 1")
    foreach(group RANGE ${last_group})
      math(EXPR first "${group} * ${GROUP_SIZE}")
      list(SUBLIST grouped ${first} ${GROUP_SIZE} members)
      list(JOIN members ":" filter)
      math(EXPR group_number "${group} + 1")
      if(group_count EQUAL 1)
        register("${suite}.*" "${filter}")
      else()
        register("${suite}.*(${group_number}/${group_count})" "${filter}")
      endif()
    endforeach()
  endif()
  foreach(test IN LISTS slow)
    register("${test}" "${test}")
  endforeach()
endforeach()

string(APPEND script "set(${TEST_TARGET}_TESTS [==[${registered}]==])\n")
file(WRITE "${CTEST_FILE}" "${script}")
