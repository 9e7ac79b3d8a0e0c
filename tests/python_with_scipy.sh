#!/usr/bin/env bash
# Prints the first Python 3 that imports scipy and numpy (Debian's python3-scipy lives in
# /usr/bin/python3's path; a pyenv or venv python3 earlier in PATH may lack it). Exits 77,
# ctest's skip code in these tests, with the reason on stderr when there is none.
for python in /usr/bin/python3 python3; do
  if command -v "$python" >/dev/null 2>&1 &&
    "$python" -c 'import scipy.stats, numpy' >/dev/null 2>&1; then
    command -v "$python"
    exit 0
  fi
done
echo "SKIP: no python3 with scipy and numpy (Debian: apt-get install python3-scipy)" >&2
exit 77
