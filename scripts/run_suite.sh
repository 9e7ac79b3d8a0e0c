#!/usr/bin/env bash
# README command 1: install dependencies, build Release, run the default suite
# into a new results/<run-id>/ folder (results.json + report.md).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh
cmake --preset release
cmake --build --preset release
./build/release/bin/tessbench run --out results "$@"
