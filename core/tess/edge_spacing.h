// Placement of points along one tessellated edge (or one inside axis) for a given level
// and parity, in 16.16 fixed point. This is the core of the D3D11 tessellator (D3D11.3
// functional spec §11): every domain coordinate in the triangle, quad and isoline
// domains is either 0, 1 or a value produced here.
#pragma once

#include "core/tess/fixed_point.h"

namespace tb::tess {

// An odd level has a middle segment; an even level has a middle point at exactly 0.5.
// Integer spacing picks the parity per level from the rounded level; the fractional
// spacings fix it for all levels.
enum class Parity { kEven, kOdd };

// Everything needed to place the points of one level (the reference tessellator's
// per-level "context"). A fractional level is split into half-levels: each half of the
// edge is laid out as if it had floor(half) or ceil(half) segments, and the point
// positions are blended by the fraction of the half-level, so that new points grow
// out of existing ones in a fixed order as the level rises.
struct EdgeSpacing {
  Parity parity = Parity::kOdd;
  int point_count = 2;                // points on the edge, both ends included
  int half_points = 1;                // points on one half before the middle (odd: includes one
                                      // middle-segment end; even: excludes the middle point)
  int split_point = 2;                // index past which the floor layout lags one point behind
  fxp::Fixed half_fraction = 0;       // fractional part of the half-level
  fxp::Fixed inv_floor_segments = 0;  // 1 / segments of the floor layout
  fxp::Fixed inv_ceil_segments = 0;   // 1 / segments of the ceil layout
};

// level: a processed level in 16.16 (already clamped and, for integer spacing, rounded).
EdgeSpacing makeEdgeSpacing(fxp::Fixed level, Parity parity);

// Position in [0, 1] of point `index` (0 .. point_count - 1). Points past the middle are
// computed as 1 - (position of the mirrored index), so an edge is exactly symmetric and
// two patches walking a shared edge in opposite directions get mirrored coordinates.
fxp::Fixed placePoint(const EdgeSpacing& spacing, int index);

}  // namespace tb::tess
