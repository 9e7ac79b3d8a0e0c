// The error_bound factor policy's per-patch inputs (factor_policy.h, FactorPolicyKind::
// kErrorBound): the technique's second-derivative bounds (techniques::CurvatureBounds) and
// the hulls the policy reads its nearest depth from, rounded outward to float once per asset.
//
// The policy aims at the tessellation error itself: an edge whose curve C has sup|C''| <= M
// needs n >= sqrt(M / (8 eps)) segments for a chord error of eps (Wang's formula), and the
// inside of a patch n >= sqrt((uu + 2 uv + vv) / (8 eps)) (Filip, Magedson & Markot 1986),
// with eps the world error that projects to the pixel target at the hull's nearest depth.
// The inside level is chosen against the tessellator's own triangles, transition rings
// included (transition_extents.h).
//
// Crack safety: a shared edge's record (its bound and its sphere) is computed once from every
// side's edge curve (the larger bound, a sphere around every side's edge hull) and copied to
// each side, so the patches of that edge compute its level from the same bits.
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
