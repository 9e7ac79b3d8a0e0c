#!/usr/bin/env bash
# Regenerates the committed baseline of deterministic figures, results/baseline/results.json:
# builds Release, runs the default suite into a temporary folder and copies its results.json
# (and writes results/baseline/README.md). Run it when a change alters a figure on purpose,
# and commit results/baseline in the same commit as that change; ctest
# Baseline.DefaultSuiteMatchesBaseline (tests/baseline) then holds every later commit to it.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --preset release >/dev/null
cmake --build --preset release
tessbench=build/release/bin/tessbench
scratch=$(mktemp -d "${TMPDIR:-/tmp}/tessbench_baseline.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
options=(--quiet)
if "$tessbench" run --help 2>/dev/null | grep -q -- '--no-pictures'; then
  options+=(--no-pictures)
fi
start=$(date +%s)
if ! "$tessbench" run "${options[@]}" --out "$scratch" --run-id baseline; then
  echo "update_baseline: the default suite did not run cleanly; the baseline is unchanged" >&2
  exit 1
fi
seconds=$(($(date +%s) - start))
mkdir -p results/baseline
cp "$scratch/baseline/results.json" results/baseline/results.json
device=$(grep -m1 '"vulkan_device"' results/baseline/results.json | sed 's/.*: *"\(.*\)",*/\1/' || true)
cat >results/baseline/README.md <<README
# Baseline of deterministic figures

\`results.json\` here is the default suite's output (\`tessbench run\` with no selection:
every technique, variant, bundled asset and measure on the default grid), the figures every
commit is compared with. ctest \`Baseline.DefaultSuiteMatchesBaseline\` (tests/baseline, run by
\`scripts/test.sh\` and so by CI) runs the default suite again and fails when
\`tessbench compare results/baseline <new run>\` finds a regression or a missing figure, with
compare's default thresholds (relative 1e-9, each metric by its declared direction). Timings are
not part of it: they vary from machine to machine (\`tessbench compare\` tests them between two
runs with \`run --repetitions\`, by a Mann–Whitney U test).

When a change alters a figure on purpose (a technique made more accurate, a measure
redefined, a new asset, technique or metric), update the baseline **in the same commit**:

    scripts/update_baseline.sh

It builds Release, runs the default suite into a temporary folder (${seconds} s wall when it was
last written) and copies its \`results.json\` here. Read \`git diff results/baseline\` before
committing: every changed figure should be one the change meant to change.

Last written from git $(git rev-parse --short HEAD 2>/dev/null || echo unknown) on
$(date -u +%Y-%m-%d), Vulkan device: ${device:-none}.
README
echo "baseline written to results/baseline/ (default suite: ${seconds} s)"
