#include "core/tess/stitch.h"

#include <bit>
#include <cassert>

namespace tb::tess {
namespace {

// Cursors walking both rows; each step emits one triangle and advances one row.
struct StripWalker {
  TriangleSink& sink;
  Row inside;
  Row outside;
  size_t in = 0;
  size_t out = 0;

  void advanceOutside() {
    assert(out + 1 < outside.size() && in < inside.size());
    sink.add(outside[out], outside[out + 1], inside[in]);
    ++out;
  }
  void advanceInside() {
    assert(in + 1 < inside.size() && out < outside.size());
    sink.add(inside[in], outside[out], inside[in + 1]);
    ++in;
  }
  // One quad between the rows, split along inside[in] -> outside[out + 1].
  void quadDiagonalFromInside() {
    sink.add(inside[in], outside[out], outside[out + 1]);
    sink.add(inside[in], outside[out + 1], inside[in + 1]);
    ++in;
    ++out;
  }
  // The same cut, emitting the outside triangle first (the odd centre strip's order).
  void quadDiagonalFromInsideOutsideFirst() {
    sink.add(outside[out], outside[out + 1], inside[in]);
    sink.add(inside[in], outside[out + 1], inside[in + 1]);
    ++in;
    ++out;
  }
  // One quad split along outside[out] -> inside[in + 1].
  void quadDiagonalFromOutside() {
    sink.add(outside[out], inside[in + 1], inside[in]);
    sink.add(outside[out], outside[out + 1], inside[in + 1]);
    ++in;
    ++out;
  }
};

// Half an edge holds at most 32 point positions (level 64). Step k = 1..32 of the ruler
// order reveals position t, where k - 1 = 2^s * (2i + 1) and t = 2^(4 - s) + i: the
// midpoint-most positions appear first, then the quarter points, and so on. Step 1
// reveals nothing (t = 32 is never below a half-point count); step 0 is position 0,
// handled by the callers. This is the order behind the reference tessellator's
// stitching table.
constexpr int kRulerSteps = 32;
constexpr int rulerPosition(int step) {
  if (step == 1) return kRulerSteps;
  const auto k = static_cast<unsigned>(step - 1);
  const int s = std::countr_zero(k);
  const int i = static_cast<int>(k >> (s + 1));
  return (1 << (4 - s)) + i;
}
static_assert(rulerPosition(2) == 16 && rulerPosition(3) == 8 && rulerPosition(4) == 17 &&
              rulerPosition(17) == 1 && rulerPosition(25) == 3 && rulerPosition(32) == 31);

}  // namespace

void stitchRegular(TriangleSink& sink, bool trapezoid, Diagonals diagonals, Row inside,
                   Row outside) {
  assert(!inside.empty() && outside.size() == inside.size() + (trapezoid ? 2 : 0));
  StripWalker walk{sink, inside, outside};
  const int quads = static_cast<int>(inside.size()) - 1;
  if (trapezoid) walk.advanceOutside();
  switch (diagonals) {
    case Diagonals::kInsideToOutside:
      for (int q = 0; q < quads; ++q) walk.quadDiagonalFromInside();
      break;
    case Diagonals::kInsideToOutsideExceptMiddle: {
      // Assumes an odd number of quads; the middle one is cut the other way.
      assert(quads % 2 == 1);
      const int half = static_cast<int>(inside.size()) / 2 - 1;
      for (int q = 0; q < half; ++q) walk.quadDiagonalFromInsideOutsideFirst();
      walk.quadDiagonalFromOutside();
      for (int q = half + 1; q < quads; ++q) walk.quadDiagonalFromInsideOutsideFirst();
      break;
    }
    case Diagonals::kMirrored: {
      const int half = static_cast<int>(inside.size()) / 2;
      int q = 0;
      for (; q < half; ++q) walk.quadDiagonalFromOutside();
      for (; q < quads; ++q) walk.quadDiagonalFromInside();
      break;
    }
  }
  if (trapezoid) walk.advanceOutside();
}

void stitchTransition(TriangleSink& sink, Row inside, const EdgeSpacing& inside_spacing,
                      Row outside, const EdgeSpacing& outside_spacing) {
  assert(!inside.empty() && outside.size() >= 2);
  StripWalker walk{sink, inside, outside};
  const bool inside_odd = inside_spacing.parity == Parity::kOdd;
  const bool outside_odd = outside_spacing.parity == Parity::kOdd;
  // Positions on each half before the middle (an odd edge's middle segment excluded).
  const int inside_half = inside_spacing.half_points - (inside_odd ? 1 : 0);
  const int outside_half = outside_spacing.half_points - (outside_odd ? 1 : 0);

  // First half, from the row starts towards the middle.
  if (outside_half > 0) walk.advanceOutside();
  for (int step = 1; step <= kRulerSteps; ++step) {
    const int position = rulerPosition(step);
    if (position < inside_half) walk.advanceInside();
    if (position < outside_half) walk.advanceOutside();
  }

  // Middle: both odd leaves a quad; mixed parity leaves one triangle pointing at the
  // row that has the middle segment; both even meet at their middle points.
  if (inside_odd && outside_odd) {
    sink.add(inside[walk.in], outside[walk.out], inside[walk.in + 1]);
    sink.add(inside[walk.in + 1], outside[walk.out], outside[walk.out + 1]);
    ++walk.in;
    ++walk.out;
  } else if (outside_odd) {
    sink.add(inside[walk.in], outside[walk.out], outside[walk.out + 1]);
    ++walk.out;
  } else if (inside_odd) {
    walk.advanceInside();
  }

  // Second half mirrors the first: same steps in reverse, outside before inside.
  for (int step = kRulerSteps; step >= 1; --step) {
    const int position = rulerPosition(step);
    if (position < outside_half) walk.advanceOutside();
    if (position < inside_half) walk.advanceInside();
  }
  if (outside_half > 0) walk.advanceOutside();
}

}  // namespace tb::tess
