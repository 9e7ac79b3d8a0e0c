// Triangulation of the strip between two rows of points (an outer ring edge and the
// inner ring edge facing it), as the D3D11 reference tessellator orders it. Rows are
// explicit lists of point indices, so a ring that wraps around, or a degenerate inner
// "ring" that is a single row walked back and forth, needs no index arithmetic.
// Internal to tb_tess.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/tess/edge_spacing.h"

namespace tb::tess {

using Row = std::span<const uint32_t>;

// Collects triangles. Triangles are given in the reference tessellator's "clockwise"
// order, which is counter-clockwise in the (u, v) plane with v pointing up, i.e. GL's
// and Vulkan-with-lower-left-origin's layout(ccw). Mesa's draw module passes the
// inverse of the shader's cw flag to the reference tessellator for this reason.
class TriangleSink {
 public:
  TriangleSink(std::vector<std::array<uint32_t, 3>>* out, bool ccw) : out_(out), ccw_(ccw) {}
  void add(uint32_t a, uint32_t b, uint32_t c) {
    out_->push_back(ccw_ ? std::array<uint32_t, 3>{a, b, c} : std::array<uint32_t, 3>{a, c, b});
  }

 private:
  std::vector<std::array<uint32_t, 3>>* out_;
  bool ccw_;
};

// Where quad diagonals point when both rows advance together.
enum class Diagonals {
  kInsideToOutside,              // every diagonal from inside[i] to outside[i + 1]
  kInsideToOutsideExceptMiddle,  // same, but the middle quad flips (odd strips)
  kMirrored,                     // first half flipped, second half not: symmetric strip
};

// Two rows whose point counts differ by 0 (trapezoid = false) or 2 (trapezoid = true:
// one extra corner triangle at each end). inside.size() is the inside point count.
void stitchRegular(TriangleSink& sink, bool trapezoid, Diagonals diagonals, Row inside,
                   Row outside);

// The first ring in from the patch edge, whose point counts are arbitrary: the two
// rows advance in the ruler order in which points appear on a half edge as the level
// grows, so the triangulation changes gradually with the levels.
void stitchTransition(TriangleSink& sink, Row inside, const EdgeSpacing& inside_spacing,
                      Row outside, const EdgeSpacing& outside_spacing);

}  // namespace tb::tess
