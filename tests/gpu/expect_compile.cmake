# cmake -DCXX=... -DSOURCE=... -DINCLUDE=... -DEXTRA=... -DEXPECT=pass|static_assert -P this:
# compiles SOURCE (syntax only) and checks the outcome (the layout compile-fail tests).
execute_process(COMMAND ${CXX} -std=c++20 -fsyntax-only -I${INCLUDE} ${EXTRA} ${SOURCE}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(EXPECT STREQUAL "pass")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "expected to build:\n${out}")
  endif()
elseif(rc EQUAL 0 OR NOT out MATCHES "static assert")
  message(FATAL_ERROR "expected a failed static_assert (rc ${rc}):\n${out}")
endif()
message(STATUS "as expected (rc ${rc})")
