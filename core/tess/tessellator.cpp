// tb::tess::tessellate: a CPU model of lavapipe's fixed-function tessellator (Mesa 22.3 runs
// Microsoft's D3D11 reference tessellator; D3D11.3 functional spec §11, the Vulkan spec's
// "Tessellation" chapter). The rules it reproduces (levels and clamping, 16.16 placement,
// rings and stitching, winding) and the output order, with the file that implements each:
// docs/derivations/tessellator.md.
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
