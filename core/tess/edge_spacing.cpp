#include "core/tess/edge_spacing.h"

#include <cassert>

namespace tb::tess {

using fxp::Fixed;

EdgeSpacing makeEdgeSpacing(Fixed level, Parity parity) {
  assert(level >= fxp::kOne && level <= 64 * fxp::kOne);  // clamped to [1, 64] by the plan
  const bool odd = parity == Parity::kOdd;
  EdgeSpacing s;
  s.parity = parity;

  // Point count: odd levels round the half-level (plus the half middle segment) up,
  // even ones round the half-level up and add the middle point. The +1 before halving
  // rounds the division the way the reference does.
  const Fixed half_level_raw = (level + 1) / 2;
  s.point_count = odd ? fxp::toInt(fxp::ceil(fxp::kHalf + half_level_raw) * 2)
                      : fxp::toInt(fxp::ceil(half_level_raw) * 2) + 1;

  // An odd layout measures half-levels including half of the middle segment. An even
  // level of exactly 1 (only reachable as an inside level, see level_rules.cpp) is laid
  // out like an even level of 2 so that it still has a middle point.
  Fixed half_level = half_level_raw;
  if (odd || half_level == fxp::kHalf) half_level += fxp::kHalf;
  const Fixed floor_half = fxp::floor(half_level);
  const Fixed ceil_half = fxp::ceil(half_level);
  s.half_fraction = half_level - floor_half;
  s.half_points = fxp::toInt(ceil_half);

  // The floor layout has one point fewer per half; which point is missing follows the
  // ruler order in which points appear as the level grows (the missing point's index is
  // twice the half-level with its top bit cleared, plus one).
  if (ceil_half == floor_half) {
    s.split_point = s.half_points + 1;  // no fraction: never split
  } else if (odd) {
    s.split_point =
        floor_half == fxp::kOne ? 0 : (fxp::removeHighestBit(fxp::toInt(floor_half) - 1) << 1) + 1;
  } else {
    s.split_point = (fxp::removeHighestBit(fxp::toInt(floor_half)) << 1) + 1;
  }

  int floor_segments = fxp::toInt(floor_half * 2);
  int ceil_segments = fxp::toInt(ceil_half * 2);
  if (odd) {
    --floor_segments;
    --ceil_segments;
  }
  s.inv_floor_segments = fxp::reciprocal(floor_segments);
  s.inv_ceil_segments = fxp::reciprocal(ceil_segments);
  return s;
}

Fixed placePoint(const EdgeSpacing& spacing, int index) {
  assert(index >= 0 && index < spacing.point_count);
  const bool odd = spacing.parity == Parity::kOdd;
  bool mirrored = false;
  int point = index;
  if (point >= spacing.half_points) {
    point = 2 * spacing.half_points - point - (odd ? 1 : 0);
    mirrored = true;
  }
  // The middle point of an even edge is set directly: the blend below cannot reach
  // 0.5 exactly in 16 bits.
  if (point == spacing.half_points) return fxp::kHalf;

  const auto on_ceil = static_cast<Fixed>(point);
  const Fixed on_floor = point > spacing.split_point ? on_ceil - 1 : on_ceil;
  const Fixed at_floor = on_floor * spacing.inv_floor_segments;
  const Fixed at_ceil = on_ceil * spacing.inv_ceil_segments;
  // Both positions are <= 0.5, so the 32-bit blend cannot overflow (the reference
  // relies on the same bound).
  Fixed location = at_floor * (fxp::kOne - spacing.half_fraction) + at_ceil * spacing.half_fraction;
  location = (location + fxp::kHalf) >> fxp::kFractionBits;
  return mirrored ? fxp::kOne - location : location;
}

}  // namespace tb::tess
