# CTest test: the tests CTest registered under PREFIX are as many as the Catch2 cases of BINARY.
# usage: cmake -DBINARY=tests_X "-DPREFIX=X: " -DCTEST=ctest -P count_tests.cmake
# Catch2 2.x exits with the number of cases listed, so the exit code says nothing here.
execute_process(COMMAND ${BINARY} --list-test-names-only OUTPUT_VARIABLE names)
string(REPLACE ";" "," names "${names}")  # a ';' in a name is one name to Catch2
string(REGEX MATCHALL "[^\n]+" catch_names "${names}")
list(LENGTH catch_names catch_count)
execute_process(COMMAND ${CTEST} -N -R "^${PREFIX}" OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
string(REGEX MATCH "Total Tests: ([0-9]+)" _ "${listing}")
set(ctest_count ${CMAKE_MATCH_1})
if(NOT ctest_count EQUAL catch_count)
  message(FATAL_ERROR "${BINARY}: Catch2 has ${catch_count} cases, CTest registered "
                      "${ctest_count} under '${PREFIX}' (a name with ';' splits in two)")
endif()
message(STATUS "${BINARY}: ${catch_count} cases, all registered")
