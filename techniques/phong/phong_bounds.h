// Culling bounds (PatchCullBounds, techniques/technique.h) of Phong tessellation, in world
// units. Plain Phong is a quadratic triangle patch: its six control points are the hull and
// its quadratic normal patch the generators. The per-edge variant is rational: its hull is
// the corners plus the corners of the offset box (24 points), with no normal generators.
// Derivation: docs/derivations/normal_cones.md (Boubekeur & Alexa 2008).
#pragma once

#include <vector>

#include "techniques/phong/phong_edge_eval.h"
#include "techniques/phong/phong_eval.h"
#include "techniques/technique.h"

namespace tb::phong {

// b_200, b_110, b_101, b_020, b_011, b_002 of the corners in the given order (the net
// order of techniques/common/patch_bounds.h).
std::vector<mesh::Vec3d> phongQuadraticNet(const PhongTriangle<double>& tri, double alpha);

// Hull and generators, oriented as the corners' order: front-facing for the face's order.
techniques::PatchCullBounds phongCullBounds(const PhongTriangle<double>& tri, double alpha);

// The per-edge variant's hull (24 points), no generators.
techniques::PatchCullBounds phongEdgeCullBounds(const PhongEdgeTriangle<double>& tri, double alpha);

}  // namespace tb::phong
