// The error_bound factor policy's per-patch inputs (factor_policy.h, kErrorBound): the
// technique's second-derivative bounds and the hulls the policy reads its nearest depth from,
// rounded outward to float once per asset. Edges by Wang's formula, the inside against the
// tessellator's own triangles (transition_extents.h; Filip, Magedson & Markot 1986). A shared
// edge's record is built once from every side and copied to each, so both compute one level.
// Derivation: docs/derivations/factor_policy.md and gregory_blend_constants.md.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "techniques/technique.h"

namespace tb::lod {

struct ErrorBoundPatch {
  // Per outer edge (gl_TessLevelOuter order): a sphere around the edge curve's hull, xyz its
  // centre and w its radius, world units.
  std::array<std::array<float, 4>, 4> edge_sphere{};
  // Per outer edge: sup|C''| / 8, world units (rounded up to float). 0 for a straight edge
  // (best: one segment); larger needs more segments, as the square root.
  std::array<float, 4> edge_m{};
  std::array<float, 4> patch_sphere{};  // around the patch's hull, as edge_sphere
  // The patch's chord-error coefficients along u and v: (uu + uv) / 8 and (vv + uv) / 8,
  // world units, rounded up. A triangle of the patch's domain whose extents are du, dv is
  // within inner_a du^2 + inner_b dv^2 of the surface (transition_extents.h); a regular n x n
  // grid within (inner_a + inner_b) / n^2. 0 for a flat patch (best); larger needs more.
  float inner_a = 0, inner_b = 0;
};

struct ErrorBounds {
  std::vector<ErrorBoundPatch> patches;  // one per patch; empty when `unavailable`
  std::string unavailable;               // why there are none ("patch 3 has no ...")
};

// The records of every patch (SurfacePatches order). Deterministic; parallel inside.
ErrorBounds errorBounds(const techniques::SurfacePatches& patches);

}  // namespace tb::lod
