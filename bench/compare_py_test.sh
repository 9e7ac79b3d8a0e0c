#!/usr/bin/env bash
# ctest Bench.ComparePyReadsOurJson: the Google Benchmark JSON our suites write stays what
# Google Benchmark's tools/compare.py (Debian libbenchmark-tools) reads. Two runs of one fast
# benchmark of tess_bench, 2 repetitions each (compare.py's UTEST_MIN_REPETITIONS), compared in
# `benchmarks` mode: it must exit 0 and print its Mann-Whitney U test line. Skipped (exit 77)
# when compare.py or a python with scipy and numpy is missing.
# Usage: compare_py_test.sh TESS_BENCH SCRATCH_DIR
set -euo pipefail
bench=$1
scratch=$2
compare_py=${TB_COMPARE_PY:-/usr/share/benchmark/compare.py}
if [[ ! -f $compare_py ]]; then
  echo "SKIP: $compare_py not found (Debian: apt-get install libbenchmark-tools)"
  exit 77
fi
python=$("$(dirname "$0")/../tests/python_with_scipy.sh") || exit 77
rm -rf "$scratch"
mkdir -p "$scratch"
for run in base new; do
  "$bench" --benchmark_filter='^BM_Tessellate/domain:0/spacing:0/level:4$' \
    --benchmark_repetitions=2 --benchmark_min_time=0.01 \
    --benchmark_out="$scratch/$run.json" --benchmark_out_format=json >/dev/null 2>&1
done
status=0
output=$("$python" "$compare_py" --no-color benchmarks "$scratch/base.json" "$scratch/new.json" 2>&1) ||
  status=$?
echo "$output"
if [[ $status -ne 0 ]]; then
  echo "FAIL: compare.py exited $status on our JSON"
  exit 1
fi
if ! grep -q 'U Test, Repetitions: 2 vs 2' <<<"$output"; then
  echo "FAIL: compare.py printed no U test line"
  exit 1
fi
rm -rf "$scratch"
