#!/usr/bin/env bash
# ctest MannWhitney.MatchesInstalledScipy: mann_whitney_scipy_check.py under a python that
# has scipy; skipped (exit 77) when none has.
set -euo pipefail
python=$("$(dirname "$0")/../python_with_scipy.sh") || exit 77
exec "$python" "$(dirname "$0")/mann_whitney_scipy_check.py" "$1"
