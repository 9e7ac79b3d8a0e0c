# Runs one libFuzzer target for ctest (CMakeLists.txt here):
#   cmake -DFUZZER=<exe> -DCORPUS=<seed dir> -DARTIFACTS=<dir/> [-DSCRATCH=<dir>]
#         -DOPTIONS=<libFuzzer flags> -P run_fuzzer.cmake
# With SCRATCH, the seeds are copied there first (a fresh copy each run) and the fuzzer grows
# that copy, never the seed folder; without it the seed folder is only read (-runs=0).
# Fails when the fuzzer exits non-zero: a crash, sanitizer report, leak, timeout or OOM,
# whose input libFuzzer saved under ARTIFACTS.
foreach(var FUZZER CORPUS ARTIFACTS OPTIONS)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_fuzzer.cmake: ${var} is not set")
  endif()
endforeach()
file(MAKE_DIRECTORY ${ARTIFACTS})
set(corpus ${CORPUS})
if(DEFINED SCRATCH)
  file(REMOVE_RECURSE ${SCRATCH})
  file(MAKE_DIRECTORY ${SCRATCH})
  file(COPY ${CORPUS}/ DESTINATION ${SCRATCH})
  set(corpus ${SCRATCH})
endif()
execute_process(COMMAND ${FUZZER} ${OPTIONS} ${corpus} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} exited with ${result}: a finding; its input is in ${ARTIFACTS}")
endif()
