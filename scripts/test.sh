#!/usr/bin/env bash
# README command 2: install every dependency (a no-op when present), build (Release) and run
# every test with ctest.
# With the argument asan-ubsan, the same tests run under AddressSanitizer and
# UndefinedBehaviorSanitizer instead; with fuzz, the libFuzzer targets of tests/fuzz
# (clang 14) replay their corpora and fuzz for TB_FUZZ_SECONDS (30) each.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
./scripts/install_deps.sh
cmake --preset "$preset"
cmake --build --preset "$preset"
ctest --preset "$preset" -j2
