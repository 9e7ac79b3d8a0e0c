#!/usr/bin/env bash
# Runs every Google Benchmark suite and writes its JSON into results/bench/<timestamp>/,
# one <suite>.json per executable, so tools/compare.py (libbenchmark-tools) can diff runs.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release
out="results/bench/$(date -u +%Y%m%d-%H%M%S)"
mkdir -p "$out"
for exe in build/release/bench/*_bench; do
  name=$(basename "$exe")
  "$exe" --benchmark_out="$out/$name.json" --benchmark_out_format=json "$@"
done
echo "benchmark JSON written to $out/"
