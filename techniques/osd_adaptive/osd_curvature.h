// Second-derivative bounds (CurvatureBounds, techniques/technique.h) of osd_adaptive's Far
// sub-patches (osd_basis.h's conventions), in the sub-patch's local (s, t); the caller
// scales them by 4^depth to the base face's (u, v). Regular patches: the B-spline's second
// differences (convex blends); Gregory end caps: curvature_bounds.h's Gregory bound.
// Derivation: docs/derivations/curvature_bounds.md.
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
