#!/usr/bin/env bash
# The relocatable bundle (scripts/bundle.sh) on a machine that has a Vulkan driver and nothing
# else: bundle this build into a temporary folder, then, in a private mount namespace, hide
# the source and build trees (an empty tmpfs over them), every system copy of a library the
# bundle carries (/dev/null bound over it) and Debian's Chart.js, and run the bundle from
# another folder: `list assets`, a small run (results.json, report.html with Chart.js inlined)
# and a benchmark whose JSON names the device. Controls: a second bundle into the same folder
# is refused, and the bare binary without the launcher's library path does not start.
# Usage: bundle_test.sh SOURCE_DIR BUILD_DIR. Exit 77 (skipped) without mount namespaces.
set -euo pipefail
src=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
tmp=$(mktemp -d /tmp/tb_bundle_test.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$src/scripts/bundle.sh" "$tmp/bundle" --build-dir "$build"
if "$src/scripts/bundle.sh" "$tmp/bundle" --build-dir "$build" 2>"$tmp/again.err"; then
  fail "a second bundle into the same folder was not refused"
fi
grep -q "is not empty" "$tmp/again.err" || fail "refusal does not say why: $(cat "$tmp/again.err")"

if ! unshare --mount --map-root-user true 2>/dev/null; then
  echo "skipped: no mount namespace here (unshare --mount --map-root-user)"
  exit 77
fi
# The system files the bundle replaces, resolved through their symlinks.
hidden=()
ldd "$build/bin/tessbench" "$build"/bench/*_bench >"$tmp/ldd.txt" 2>/dev/null || true  # no bench/ in some presets
for lib in "$tmp"/bundle/lib/*; do
  name=$(basename "$lib")
  system=$(awk -v n="$name" '$1 == n && $3 ~ /^\// {print $3; exit}' "$tmp/ldd.txt")
  if [[ -n $system ]]; then hidden+=("$(readlink -f "$system")"); fi
done
(( ${#hidden[@]} > 5 )) || fail "expected the bundle to replace several system libraries: ${hidden[*]}"
mkdir -p "$tmp/elsewhere"

cat >"$tmp/inside.sh" <<'EOF'
set -euo pipefail
src=$1 build=$2 tmp=$3
shift 3
mount -t tmpfs tmpfs "$src"
case $build in "$src"/*) ;; *) mount -t tmpfs tmpfs "$build" ;; esac
for file in "$@"; do mount --bind /dev/null "$file"; done
[[ -d /usr/share/javascript ]] && mount -t tmpfs tmpfs /usr/share/javascript
cd "$tmp/elsewhere"
[[ ! -e $build/bin/tessbench ]] || { echo "FAIL: the build tree is still visible" >&2; exit 1; }
# Control: without the launcher's library path the binary cannot load its libraries.
if "$tmp/bundle/bin/tessbench" --version >/dev/null 2>&1; then
  echo "FAIL: the bare binary started: the system libraries are not hidden" >&2; exit 1
fi
"$tmp/bundle/tessbench" list assets >assets.txt
grep -q catmark_cube assets.txt || { echo "FAIL: the bundle lists no bundled assets" >&2; exit 1; }
"$tmp/bundle/tessbench" run --quiet --no-pictures --technique phong --asset catmark_cube \
  --measure cracks --out results --run-id bundled
grep -q '"vulkan_device"' results/bundled/results.json
grep -q 'Chart.js v' results/bundled/report.html || { echo "FAIL: report.html has no Chart.js" >&2; exit 1; }
if [[ ! -e $tmp/bundle/tess_bench ]]; then  # a preset without benchmarks (asan-ubsan)
  echo "bundle ran from $tmp/elsewhere (no benchmarks in this build)"
  exit 0
fi
"$tmp/bundle/tess_bench" --benchmark_filter='BM_Tessellate/domain:0/spacing:0/level:4$' \
  --benchmark_min_time=0.01 --benchmark_out=bench.json --benchmark_out_format=json >/dev/null
grep -q '"vulkan_device"' bench.json || { echo "FAIL: the benchmark JSON names no device" >&2; exit 1; }
echo "bundle ran from $tmp/elsewhere with the build tree and ${#@} system libraries hidden"
EOF
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0} \
  unshare --mount --map-root-user bash "$tmp/inside.sh" "$src" "$build" "$tmp" "${hidden[@]}"
