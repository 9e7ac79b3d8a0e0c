// Triangle domain (D3D11.3 functional spec §11, triangle patch; Vulkan spec "Triangle
// Tessellation"). Concentric triangular rings: ring 0 is the patch boundary with one
// spacing per edge, rings 1.. use the inside level. Stored coordinates are (u, v); the
// rings are walked clockwise in the reference's sense starting at the v = 1 corner:
// edge u = 0 (v falling), edge v = 0 (u rising), edge w = 0 (u falling).
#include <cassert>
#include <vector>

#include "core/tess/domains.h"
#include "core/tess/stitch.h"

namespace tb::tess {
namespace {

using fxp::Fixed;
using fxp::kOne;

constexpr size_t kEdges = 3;

RingRows boundaryRing(const TrianglePlan& plan, PointWriter& points) {
  RingRows ring;
  for (size_t e = 0; e < kEdges; ++e) {
    const EdgeSpacing& spacing = plan.outer[e];
    const int last = spacing.point_count - 1;
    for (int p = 0; p < last; ++p) {
      const Fixed t = placePoint(spacing, e == 1 ? p : last - p);
      const Fixed u = e == 0 ? 0 : t;
      const Fixed v = e == 0 ? t : (e == 1 ? 0 : kOne - t);
      ring[e].push_back(points.add(u, v));
    }
  }
  closeRing(&ring, kEdges);
  return ring;
}

// Inner ring r lies at distance place(r) from each edge, measured along the edge's own
// axis; in barycentric terms that is 2/3 of it (the perpendicular coordinate), and the
// points along the ring shift by half of that so the ring stays centred. Both steps
// round in 16.16 exactly as the reference tessellator does.
RingRows innerRing(const EdgeSpacing& inner, int r, PointWriter& points) {
  RingRows ring;
  const int end = inner.point_count - 1 - r;
  const Fixed perp = (placePoint(inner, r) * fxp::kTwoThirds + fxp::kHalf) >> fxp::kFractionBits;
  const Fixed shift = (perp + 1) / 2;
  for (size_t e = 0; e < kEdges; ++e) {
    for (int p = r; p < end; ++p) {
      const Fixed along = placePoint(inner, e == 1 ? p : end - (p - r)) - shift;
      uint32_t index = 0;
      if (e == 0) {
        index = points.add(perp, along);
      } else if (e == 1) {
        index = points.add(along, perp);
      } else {
        index = points.add(along, kOne - along - perp);
      }
      ring[e].push_back(index);
    }
  }
  closeRing(&ring, kEdges);
  return ring;
}

}  // namespace

void tessellateTriangleDomain(const TrianglePlan& plan, const Options& options, Tessellation* out) {
  assert(out != nullptr && out->points.empty() && !plan.culled);
  PointWriter points(out, /*barycentric=*/true);
  TriangleSink sink(&out->triangles, options.ccw);
  if (plan.minimal) {
    // The corners in ring order: v = 1, w = 1, u = 1.
    points.add(0, kOne);
    points.add(0, 0);
    points.add(kOne, 0);
    if (!options.point_mode) sink.add(0, 1, 2);
    return;
  }

  const int inner_points = plan.inner.point_count;
  const bool odd = plan.inner.parity == Parity::kOdd;
  // Upper bounds: the boundary plus rings of at most 3 * inner_points points each;
  // about two triangles a point.
  size_t boundary = 0;
  for (const EdgeSpacing& edge : plan.outer) boundary += static_cast<size_t>(edge.point_count);
  const auto inner = static_cast<size_t>(inner_points);
  out->points.reserve(boundary + 3 * inner * inner / 4 + 1);
  if (!options.point_mode) out->triangles.reserve(2 * out->points.capacity());
  std::vector<RingRows> rings;
  rings.push_back(boundaryRing(plan, points));
  for (int r = 1; r < inner_points / 2; ++r) rings.push_back(innerRing(plan.inner, r, points));
  if (!odd) {
    // An even inside level ends in the centre point, stitched as a ring whose every
    // edge row is that single point.
    const uint32_t centre = points.add(fxp::kOneThird, fxp::kOneThird);
    rings.push_back(RingRows{{{centre}, {centre}, {centre}, {}}});
  }
  if (options.point_mode) return;

  for (size_t r = 1; r < rings.size(); ++r) {
    for (size_t e = 0; e < kEdges; ++e) {
      const Row inside = rings[r][e];
      const Row outside = rings[r - 1][e];
      if (r == 1) {
        stitchTransition(sink, inside, plan.inner, outside, plan.outer[e]);
      } else {
        stitchRegular(sink, /*trapezoid=*/true, Diagonals::kMirrored, inside, outside);
      }
    }
  }
  if (odd) {
    // An odd inside level ends in a ring of three points: one triangle.
    const RingRows& last = rings.back();
    sink.add(last[0].front(), last[1].front(), last[2].front());
  }
}

}  // namespace tb::tess
