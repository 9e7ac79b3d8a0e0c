#!/usr/bin/env bash
# Bakes the displacement maps the default suite runs (assets/displacement/*.exr and their
# .exr.json sidecars): one per surface technique, from the analytic oracle target (the asset's
# limit displaced by a closed-form h; harness/bake/analytic_target.h), 16 texels a patch side,
# half floats. The test BundledMaps.EqualAFreshBake checks the bundled files are current.
# Usage: scripts/bake_default_maps.sh [path/to/tessbench]   (default build/release/bin/tessbench)
set -euo pipefail
cd "$(dirname "$0")/.."
tessbench="${1:-build/release/bin/tessbench}"
out=assets/displacement
mkdir -p "$out"
# name technique asset
while read -r name technique asset; do
  rm -f "$out/$name.exr" "$out/$name.exr.json"
  "$tessbench" bake --technique "$technique" --asset "$asset" --analytic --resolution 16 \
    --pixel-type half --out "$out/$name.exr"
done <<'MAPS'
acc_catmark_torus acc opensubdiv/catmark_torus
gregory_acc_catmark_toroidal_tet gregory_acc opensubdiv/catmark_toroidal_tet
pn_triangles_tri_torus pn_triangles tessbench/tri_torus
phong_tri_torus phong tessbench/tri_torus
MAPS
