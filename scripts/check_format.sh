#!/usr/bin/env bash
# The C++ sources as .clang-format writes them: clang-format-14 --dry-run --Werror over every
# tracked .cpp and .h (GLSL is not C++ and is left alone). Prints each file clang-format would
# change and exits 1 when there is any; 0 otherwise.
#   scripts/check_format.sh [ROOT]       the check (ctest Repo.ClangFormat)
#   scripts/check_format.sh --selftest   shows a misformatted file caught and a clean one passed
set -euo pipefail
format=${CLANG_FORMAT:-clang-format-14}
command -v "$format" >/dev/null || { echo "check_format: $format not found (scripts/install_deps.sh)"; exit 1; }
if [[ ${1:-} == --selftest ]]; then
  dir=$(mktemp -d)
  trap 'rm -rf "$dir"' EXIT
  cp "$(dirname "$0")/../.clang-format" "$dir/"
  printf 'int  f( int x ){return x;}\n' >"$dir/bad.cpp"
  printf 'int f(int x) { return x; }\n' >"$dir/good.cpp"
  if "$format" --dry-run --Werror "$dir/bad.cpp" 2>/dev/null; then
    echo "selftest: FAILED, a misformatted file passed"; exit 1
  fi
  "$format" --dry-run --Werror "$dir/good.cpp" || { echo "selftest: FAILED, a clean file failed"; exit 1; }
  echo "selftest: a misformatted file caught, a clean one passed"
  exit 0
fi
cd "${1:-$(dirname "$0")/..}"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.h')
else
  mapfile -t files < <(find core harness techniques reference bench tests examples shaders \
    -name '*.cpp' -o -name '*.h' | sort)
fi
bad=$("$format" --dry-run --Werror "${files[@]}" 2>&1 | sed -nE 's/^([^:]+):[0-9]+:[0-9]+: (warning|error):.*/\1/p' | sort -u)
count=$(printf '%s' "$bad" | grep -c . || true)
[[ -n $bad ]] && printf '%s\n' "$bad"
echo "check_format: ${#files[@]} files, $count to reformat"
[[ $count -eq 0 ]]
