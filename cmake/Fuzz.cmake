# TB_FUZZ: a build of only the libFuzzer targets in tests/fuzz and the libraries they link
# (tests/fuzz/README.md). Every library compiles with libFuzzer's coverage instrumentation
# plus ASan and UBSan; the fuzz executables add libFuzzer's main (TB_FUZZ_LINK_OPTIONS).
# Assertions stay on (-UNDEBUG after the build type's -DNDEBUG): a precondition that some
# input breaks is a finding too.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "TB_FUZZ needs clang with libFuzzer: cmake --preset fuzz "
                      "(clang++-14 and libfuzzer-14-dev on Debian 12)")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer -g -O1 -UNDEBUG)
set(TB_FUZZ_LINK_OPTIONS -fsanitize=fuzzer,address,undefined)
set(TB_FUZZ_SECONDS 30 CACHE STRING
    "Seconds each <target>_fuzz test fuzzes for (libFuzzer's -max_total_time)")
