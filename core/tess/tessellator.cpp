// tb::tess::tessellate: a CPU model of lavapipe's fixed-function tessellator.
//
// lavapipe (Mesa 22.3, gallium draw module) runs Microsoft's D3D11 reference tessellator
// and feeds its (u, v) to the TES. The rules reproduced here, with where they come from:
//  - Levels: culling on any relevant outer level that is not > 0 (NaN too); clamp ranges
//    integer/pow2 [1, 64] rounded up, fractional_odd [1, 63], fractional_even [2, 64];
//    isoline density always rounded up in [1, 64]; fractional_odd keeps the inside level
//    above 1 once any level exceeds 1; an integer inside level of 1 counts as even;
//    "every level 1" is one triangle (tri) or two (quad).
//    D3D11.3 functional spec §11 (Tessellator) and the Vulkan spec's "Tessellation"
//    chapter; the details as lavapipe applies them: patch_plan.cpp.
//  - Placement: levels in 16.16 fixed point, half-level floor/ceil blend, mirrored
//    halves, exact 0.5 middle: edge_spacing.cpp (fixed_point.h for the arithmetic).
//  - Rings and stitching: triangle_domain.cpp, quad_domain.cpp, stitch.cpp.
//  - gl_TessCoord.z = (1 - u) - v for triangles (Mesa draw_llvm.c): domains.h.
//  - Winding: the reference emits triangles counter-clockwise in (u, v) with v up for
//    layout(ccw) (Mesa passes !cw to it); Options::ccw = false swaps two vertices.
//    With Vulkan's default upper-left domain origin, lavapipe flips the shader's
//    winding, so compare against a capture made with a lower-left origin or flip ccw.
//  - pow2 (D3D HLSL only): roundPow2Levels() first, then integer spacing.
//
// Output order (the reference tessellator's own storage order, so TES invocation order
// on lavapipe matches point order):
//  - triangle: boundary ring from the v = 1 corner along u = 0, then v = 0, then w = 0;
//    then each inner ring the same way inwards; then the centre (even inside level).
//    All levels 1: (0,1), (0,0), (1,0).
//  - quad: boundary ring from (0,1) along u = 0 (v falling), v = 0, u = 1, v = 1; then
//    each inner ring the same way; then the middle row (low u to high u) or column (high
//    v to low v) of an even inside level. All levels 1: (0,0), (1,0), (1,1), (0,1).
//  - isoline: line by line from v = 0, each line from u = 0 to u = 1; line segments join
//    consecutive points of a line.
//  - triangles: ring by ring outwards-in, per ring edge by edge, then the middle.
#include "core/tess/tessellator.h"

#include <cassert>

#include "core/tess/domains.h"
#include "core/tess/patch_plan.h"

namespace tb::tess {
namespace {

void tessellateIsolineDomain(const IsolinePlan& plan, const Options& options, Tessellation* out) {
  assert(out != nullptr && out->points.empty() && !plan.culled && plan.line_count >= 1);
  PointWriter points(out, /*barycentric=*/false);
  const int per_line = plan.detail.point_count;
  out->points.reserve(static_cast<size_t>(plan.line_count) * static_cast<size_t>(per_line));
  if (!options.point_mode) out->lines.reserve(out->points.capacity());
  for (int line = 0; line < plan.line_count; ++line) {
    const fxp::Fixed v = placePoint(plan.density, line);
    for (int p = 0; p < per_line; ++p) {
      const uint32_t index = points.add(placePoint(plan.detail, p), v);
      if (p > 0 && !options.point_mode) out->lines.push_back({index - 1, index});
    }
  }
}

}  // namespace

Tessellation tessellate(Domain domain, Spacing spacing, const Levels& levels,
                        const Options& options) {
  assert(spacing >= Spacing::kInteger && spacing <= Spacing::kFractionalEven);
  Tessellation out;
  switch (domain) {
    case Domain::kTriangle: {
      const TrianglePlan plan = planTriangle(spacing, levels);
      out.culled = plan.culled;
      if (!plan.culled) tessellateTriangleDomain(plan, options, &out);
      break;
    }
    case Domain::kQuad: {
      const QuadPlan plan = planQuad(spacing, levels);
      out.culled = plan.culled;
      if (!plan.culled) tessellateQuadDomain(plan, options, &out);
      break;
    }
    case Domain::kIsoline: {
      const IsolinePlan plan = planIsoline(spacing, levels);
      out.culled = plan.culled;
      if (!plan.culled) tessellateIsolineDomain(plan, options, &out);
      break;
    }
  }
  return out;
}

}  // namespace tb::tess
