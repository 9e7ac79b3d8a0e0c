#!/usr/bin/env bash
# README command 1: install what tessbench needs to build and run (scripts/install_deps.sh
# --run), build the `tessbench` target (Release; not the tests: scripts/test.sh builds those)
# and run the default suite into a new results/<run-id>/ folder (results.json, report.md,
# report.html, tables/, pictures/). Arguments go to `tessbench run`.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh --run
cmake --preset release
cmake --build --preset release --target tessbench
./build/release/bin/tessbench run --out results "$@"
