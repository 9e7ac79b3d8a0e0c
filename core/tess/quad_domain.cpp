// Quad domain (D3D11.3 functional spec §11, quad patch; Vulkan spec "Quad
// Tessellation"). Concentric rectangular rings: ring 0 is the patch boundary with one
// spacing per edge, rings 1.. use the two inside levels. Each ring is walked starting
// at its (u low, v high) corner: edge u = 0 (v falling), v = 0 (u rising), u = 1
// (v rising), v = 1 (u falling). Where the rings run out the middle is either a
// single row or column of points (an even inside level on the shorter axis) or a
// two-row strip of quads (an odd one).
#include <algorithm>
#include <cassert>
#include <vector>

#include "core/tess/domains.h"
#include "core/tess/stitch.h"

namespace tb::tess {
namespace {

using fxp::Fixed;
using fxp::kOne;

constexpr size_t kEdges = 4;
constexpr int kU = 0;
constexpr int kV = 1;

// Edges u = 0 and v = 1 run against their axis.
bool runsForward(size_t edge) { return edge == 1 || edge == 2; }
// The axis an edge runs along: edges 0 and 2 along v, 1 and 3 along u.
int alongAxis(size_t edge) { return static_cast<int>((edge + 1) & 1); }

RingRows boundaryRing(const QuadPlan& plan, PointWriter& points) {
  RingRows ring;
  for (size_t e = 0; e < kEdges; ++e) {
    const EdgeSpacing& spacing = plan.outer[e];
    const int last = spacing.point_count - 1;
    const Fixed fixed_coordinate = (e == 2 || e == 3) ? kOne : 0;
    for (int p = 0; p < last; ++p) {
      const Fixed t = placePoint(spacing, runsForward(e) ? p : last - p);
      const bool along_v = alongAxis(e) == kV;
      ring[e].push_back(along_v ? points.add(fixed_coordinate, t)
                                : points.add(t, fixed_coordinate));
    }
  }
  closeRing(&ring, kEdges);
  return ring;
}

RingRows innerRing(const QuadPlan& plan, int r, PointWriter& points) {
  RingRows ring;
  const std::array<int, 2> end{plan.inner[kU].point_count - 1 - r,
                               plan.inner[kV].point_count - 1 - r};
  for (size_t e = 0; e < kEdges; ++e) {
    const int along = alongAxis(e);
    const int across = 1 - along;
    // Edges 0 and 1 sit at the ring's low side of the other axis, 2 and 3 at its high side.
    const Fixed offset = placePoint(plan.inner[across], e < 2 ? r : end[across]);
    for (int p = r; p < end[along]; ++p) {
      const Fixed t = placePoint(plan.inner[along], runsForward(e) ? p : end[along] - (p - r));
      ring[e].push_back(along == kV ? points.add(offset, t) : points.add(t, offset));
    }
  }
  closeRing(&ring, kEdges);
  return ring;
}

// The innermost "ring" of an even inside level on the shorter axis is a line of points
// through the middle (v = 0.5 row or u = 0.5 column). As a ring its four edges walk that
// line forward, stand on its far end, walk it back and stand on its start. The column
// is stored from high v to low v, following edge u = 0's direction.
RingRows middleLine(const QuadPlan& plan, int start, PointWriter& points, bool row) {
  std::vector<uint32_t> line;
  if (row) {
    const int last = plan.inner[kU].point_count - 1 - start;
    for (int p = start; p <= last; ++p)
      line.push_back(points.add(placePoint(plan.inner[kU], p), fxp::kHalf));
    return RingRows{{{line.front()}, line, {line.back()}, reversedRow(line)}};
  }
  const int last = plan.inner[kV].point_count - 1 - start;
  for (int p = last; p >= start; --p)
    line.push_back(points.add(fxp::kHalf, placePoint(plan.inner[kV], p)));
  return RingRows{{line, {line.back()}, reversedRow(line), {line.front()}}};
}

}  // namespace

void tessellateQuadDomain(const QuadPlan& plan, const Options& options, Tessellation* out) {
  assert(out != nullptr && out->points.empty() && !plan.culled);
  PointWriter points(out, /*barycentric=*/false);
  TriangleSink sink(&out->triangles, options.ccw);
  if (plan.minimal) {
    points.add(0, 0);
    points.add(kOne, 0);
    points.add(kOne, kOne);
    points.add(0, kOne);
    if (!options.point_mode) {
      sink.add(0, 1, 3);
      sink.add(1, 2, 3);
    }
    return;
  }

  const int n_u = plan.inner[kU].point_count;
  const int n_v = plan.inner[kV].point_count;
  const bool even_u = plan.inner[kU].parity == Parity::kEven;
  const bool even_v = plan.inner[kV].parity == Parity::kEven;
  // The shorter axis decides how the middle ends; ties go to the column/v-strip cases.
  const bool u_longer = n_u > n_v;
  const int full_rings = std::min(n_u, n_v) / 2;
  // Upper bounds: the boundary plus the full inside grid; about two triangles a point.
  size_t boundary = 0;
  for (const EdgeSpacing& edge : plan.outer) boundary += static_cast<size_t>(edge.point_count);
  out->points.reserve(boundary + static_cast<size_t>(n_u) * static_cast<size_t>(n_v));
  if (!options.point_mode) out->triangles.reserve(2 * out->points.capacity());

  std::vector<RingRows> rings;
  rings.push_back(boundaryRing(plan, points));
  for (int r = 1; r < full_rings; ++r) rings.push_back(innerRing(plan, r, points));
  if (u_longer && even_v) rings.push_back(middleLine(plan, full_rings, points, /*row=*/true));
  if (!u_longer && even_u) rings.push_back(middleLine(plan, full_rings, points, /*row=*/false));
  if (options.point_mode) return;

  for (size_t r = 1; r < rings.size(); ++r) {
    for (size_t e = 0; e < kEdges; ++e) {
      const Row inside = rings[r][e];
      const Row outside = rings[r - 1][e];
      if (r == 1) {
        stitchTransition(sink, inside, plan.inner[alongAxis(e)], outside, plan.outer[e]);
      } else {
        stitchRegular(sink, /*trapezoid=*/true, Diagonals::kMirrored, inside, outside);
      }
    }
  }

  // An odd inside level on the shorter axis leaves a two-row strip inside the last ring:
  // its long sides are stitched straight across, high side as the "inside" row.
  const RingRows& last = rings.back();
  if (u_longer && !even_v) {
    stitchRegular(sink, /*trapezoid=*/false, Diagonals::kInsideToOutside, reversedRow(last[3]),
                  last[1]);
  } else if (!u_longer && !even_u) {
    const Diagonals diagonals =
        even_v ? Diagonals::kInsideToOutside : Diagonals::kInsideToOutsideExceptMiddle;
    stitchRegular(sink, /*trapezoid=*/false, diagonals, reversedRow(last[2]), last[0]);
  }
}

}  // namespace tb::tess
