// Culling bounds (PatchCullBounds, techniques/technique.h) of Phong tessellation, in world
// units.
//
// Plain Phong (phong_eval.h) is a quadratic triangle patch. With weights w_i (Σ w_i = 1),
// flat point p = Σ_j w_j p_j and heights h_ij = (p_j - p_i)·n_i (h_ii = 0):
//   p* = p - α Σ_i w_i ((p - p_i)·n_i) n_i = Σ_i w_i² p_i + Σ_{i<j} 2 w_i w_j b_ij,
//   b_ij = (p_i + p_j) / 2 - (α / 2) (h_ij n_i + h_ji n_j),
// since (p - p_i)·n_i = Σ_j w_j h_ij and Σ_i w_i p_i = Σ_i Σ_j w_i w_j p_i. Its six control
// points are the hull and its quadratic normal patch (patch_bounds.h) the generators.
//
// The per-edge variant (phong_edge_eval.h) is rational. Its offset is Σ_e c_e(w) K_e with
// K_e = n_i h_ij + n_j h_ji (per-edge normals n) and c_e = t_i t_j w_i w_j / D, which lies
// in [0, 1/4] (w_i w_j <= D and t_i t_j <= 1/4). So p* lies in the flat triangle plus the
// box {-α Σ_e s_e K_e / 4 : s_e in [0, 1]}: the hull is every corner plus every corner of
// that box (24 points). No normal generators (an empty cone bound).
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
