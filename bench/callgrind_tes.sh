#!/bin/sh
# x86 instructions per TES invocation of a technique's GPU program on lavapipe, as the
# slope of callgrind's instruction count between two levels (docs/MEASURES.md).
#   bench/callgrind_tes.sh TECHNIQUE ASSET [VARIANT] [LEVEL_LOW LEVEL_HIGH]
# The count covers lavapipe's software tessellator and the TES JIT code together; run
# it once with a trivial program (gpu/test_bilinear via the patch-program tests) to see
# the tessellator's share. Takes about a minute: valgrind runs lavapipe ~50x slower.
set -eu
build=${BUILD_DIR:-build/release}
exe="$build/bench/tes_instructions"
technique=$1 asset=$2 variant=${3:-} low=${4:-8} high=${5:-16}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
valgrind --tool=callgrind --callgrind-out-file="$out/cg.out" \
  "$exe" "$technique" "$asset" "$variant" "$low" "$high" >/dev/null 2>"$out/log" ||
  { cat "$out/log" >&2; exit 1; }
# Each dump: "desc: Trigger: Client Request: level L tes_invocations I" and "summary: Ir".
for f in "$out"/cg.out.*; do
  inv=$(sed -n 's/.*tes_invocations \([0-9]*\).*/\1/p' "$f" | head -1)
  ir=$(sed -n 's/^summary: \([0-9]*\).*/\1/p' "$f" | head -1)
  [ -n "$inv" ] && echo "$inv $ir"
done | sort -n | awk -v t="$technique" -v a="$asset" '
  NR == 1 { i0 = $1; r0 = $2 }
  NR == 2 { i1 = $1; r1 = $2 }
  END {
    if (NR < 2 || i1 == i0) { print "callgrind_tes: need two levels with different invocation counts" > "/dev/stderr"; exit 1 }
    printf "%s on %s: %d -> %d TES invocations, %d -> %d x86 instructions; %.1f per invocation\n",
           t, a, i0, i1, r0, r1, (r1 - r0) / (i1 - i0)
  }'
