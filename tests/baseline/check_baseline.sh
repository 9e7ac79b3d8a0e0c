#!/usr/bin/env bash
# ctest Baseline.DefaultSuiteMatchesBaseline: runs the default suite and compares its
# deterministic figures with the committed baseline (results/baseline/results.json) by
# `tessbench compare`'s default thresholds. A regression or a missing figure fails; an intended
# change updates the baseline in the same commit (scripts/update_baseline.sh).
# Usage: check_baseline.sh TESSBENCH SOURCE_DIR SCRATCH_DIR
set -euo pipefail
tessbench=$1
source_dir=$2
scratch=$3
baseline="$source_dir/results/baseline"
if [[ ! -f $baseline/results.json ]]; then
  echo "FAIL: $baseline/results.json is missing; create it with scripts/update_baseline.sh" \
    "(runs the default suite and commits its results.json as the baseline)"
  exit 1
fi
rm -rf "$scratch"
mkdir -p "$scratch"
options=(--quiet)
# Pictures are no part of the comparison: skip them when this build can.
if "$tessbench" run --help 2>/dev/null | grep -q -- '--no-pictures'; then
  options+=(--no-pictures)
fi
start=$(date +%s)
# A run that exits 1 (a measure failed) still writes its folder; compare reports the figures
# it lost as missing, so the comparison, not the run's exit, decides.
"$tessbench" run "${options[@]}" --out "$scratch" --run-id current || true
if [[ ! -f $scratch/current/results.json ]]; then
  echo "FAIL: the default suite wrote no results"
  exit 1
fi
echo "default suite: $(($(date +%s) - start)) s"
# The default suite's report.md opens with the answers block and stays short: the detail
# is in tables/*.csv and results.json. 1,500 lines: the default run's report is ~1,280, of
# which ~380 are the per-asset decision tables (about 10 lines for each of 36 assets).
report=$scratch/current/report.md
lines=$(wc -l <"$report")
first_section=$(grep -m1 '^## ' "$report" || true)
echo "report.md: $lines lines, first section: $first_section"
if [[ $lines -ge 1500 || $first_section != "## Answers" ]]; then
  echo "FAIL: report.md must be under 1,500 lines and open with the answers block"
  exit 1
fi
for measure in $(ls "$scratch/current/tables" | grep -v -e warnings -e record_notes); do
  [[ -s $scratch/current/tables/$measure ]] || { echo "FAIL: tables/$measure is empty"; exit 1; }
done
status=0
"$tessbench" compare --limit 60 "$baseline" "$scratch/current" || status=$?
if [[ $status -ne 0 ]]; then
  echo
  echo "FAIL: the default suite's figures differ from results/baseline (exit $status)."
  echo "An intended change: run scripts/update_baseline.sh and commit results/baseline with it."
  echo "The new run is kept in $scratch/current."
  exit 1
fi
rm -rf "$scratch"
