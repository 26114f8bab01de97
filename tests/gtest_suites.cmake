# cmake -D EXE=TEST_BINARY -D OUT=FILE -P gtest_suites.cmake: lists the binary's
# GoogleTest suites and writes a ctest file with a test per suite ("Suite", running
# Suite.*), and a test per test in a value-parameterized suite ("Prefix/Suite.Test":
# those are few and long). Each test binary starts in 0.1-0.3 s under the sanitizers:
# a process per suite rather than per test takes a quarter off the sanitized run.
execute_process(COMMAND "${EXE}" --gtest_list_tests OUTPUT_VARIABLE listing RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXE} --gtest_list_tests failed: ${status}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(out "")
set(suite "")
set(count 0)
macro(add_one name filter cost)
  string(APPEND out "add_test([=[${name}]=] [=[${EXE}]=] [=[--gtest_filter=${filter}]=])\n"
                    "set_tests_properties([=[${name}]=] PROPERTIES TIMEOUT 600 COST ${cost})\n")
endmacro()
macro(end_suite)
  if(suite AND NOT suite MATCHES "/")
    add_one("${suite}" "${suite}.*" ${count})  # the bigger suites first
  endif()
endmacro()
foreach(line IN LISTS lines)
  if(line MATCHES "^([A-Za-z0-9_/]+)\\.$")
    set(next "${CMAKE_MATCH_1}")  # before end_suite's own MATCHES resets it
    end_suite()
    set(suite "${next}")
    set(count 0)
  elseif(line MATCHES "^  ([A-Za-z0-9_/]+)")
    set(test "${suite}.${CMAKE_MATCH_1}")
    math(EXPR count "${count} + 1")
    if(suite MATCHES "/")
      add_one("${test}" "${test}" 100)
    endif()
  endif()
endforeach()
end_suite()
file(WRITE "${OUT}" "${out}")
