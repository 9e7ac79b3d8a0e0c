// Second-derivative bounds (CurvatureBounds, techniques/technique.h) of osd_adaptive's Far
// sub-patches (osd_basis.h's conventions), in the sub-patch's local (s, t); the caller
// scales them by 4^depth to the base face's (u, v) (s = u 2^depth - U).
//
// Regular patch (bicubic uniform B-spline over 16 points, boundary edges' phantom rows
// replaced by their extrapolation 2 p1 - p2, which is what osd_basis.h's folded weights
// evaluate): along s, the second derivative of a uniform cubic B-spline segment over
// p0..p3 is (1 - s) (p0 - 2 p1 + p2) + s (p1 - 2 p2 + p3), a convex blend of the two second
// differences, and the rows are blended by the non-negative t basis summing to 1; so
// sup |S_ss| <= max over the 4 rows of the 2 second differences' norms (attained when one
// row's difference dominates at a knot; 0 on a bilinear patch). S_st: the first derivative
// is a quadratic B-spline of the first differences, so the 3 x 3 mixed differences bound
// it. Edge curves: the boundary curve s = 0 is the cubic B-spline of q_j = (p_0j + 4 p_1j +
// p_2j) / 6 (the basis at s = 0), bounded by max |Δ² q|; its hull is the q_j.
//
// Gregory basis end cap: curvature_bounds.h's Gregory bound on its 4 x 4 Bézier net (face
// points' midpoints inside, plus the blends' universal constants times |F+ - F-| / 2).
#pragma once

#include <array>
#include <cstdint>

#include "core/mesh/vec.h"
#include "techniques/osd_adaptive/osd_basis.h"
#include "techniques/technique.h"

namespace tb::osd_adaptive {

// `points`: the sub-patch's subPatchPointCount(packed) control points (16 or 20). Edges in
// CurvatureBounds order: s = 0, t = 0, s = 1, t = 1 (the base face's u = 0, v = 0, u = 1,
// v = 1 where the sub-patch touches them).
techniques::CurvatureBounds subPatchCurvatureBounds(
    uint32_t packed, const std::array<mesh::Vec3d, kMaxSubPatchPoints>& points);

}  // namespace tb::osd_adaptive
