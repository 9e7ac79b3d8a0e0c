#include "core/tess/patch_plan.h"

#include <algorithm>
#include <cmath>

#include "core/tess/factor_helpers.h"
#include "core/tess/level_rules.h"

namespace tb::tess {
namespace {

using fxp::Fixed;

// fractional_odd: once any level would exceed 1 after the fixed-point conversion (more
// than half an ulp of 16.16 above 1), the inside level is kept strictly above 1 so that
// the patch always gets an outer ring ("picture frame") to transition from the edges.
constexpr float kOddFrameThreshold = 1.0f + 0x1p-17f;
constexpr float kOddFrameInsideMinimum = 1.0f + 0x1p-16f;

Parity fixedParity(Spacing spacing) {
  return spacing == Spacing::kFractionalEven ? Parity::kEven : Parity::kOdd;
}

// Integer spacing takes the parity of each rounded level. An inside level of 1 counts
// as even: the inside then collapses to a centre point (triangle) or a middle row, which
// is what makes "inside 1, outside > 1" tessellate like the next level up.
Parity outerParity(float level, Spacing spacing) {
  if (!hardwareInteger(spacing)) return fixedParity(spacing);
  return isEvenLevel(level) ? Parity::kEven : Parity::kOdd;
}

Parity innerParity(float level, Spacing spacing) {
  if (!hardwareInteger(spacing)) return fixedParity(spacing);
  return (isEvenLevel(level) || level == 1.0f) ? Parity::kEven : Parity::kOdd;
}

float roundIfInteger(float level, Spacing spacing) {
  return hardwareInteger(spacing) ? std::ceil(level) : level;
}

// Levels to use for the hardware rules: pow2 is rounded up first (HLSL layer), then
// treated as integer.
Levels effectiveLevels(Domain domain, Spacing spacing, const Levels& levels) {
  return spacing == Spacing::kPow2 ? roundPow2Levels(domain, levels) : levels;
}

// Culling: any outer level that is not > 0 (NaN included) discards the patch.
template <size_t kCount>
bool anyCulled(const std::array<float, 4>& outer) {
  return std::any_of(outer.begin(), outer.begin() + kCount, [](float l) { return !(l > 0.0f); });
}

// Shared triangle/quad rules. Returns false when the patch is culled. `inner_raw_in_frame`
// is the quad rule that the raw inside levels also count towards the odd picture frame
// (the triangle checks its outer levels only).
template <size_t kEdges, size_t kAxes>
bool planRings(Spacing spacing, const Levels& levels, bool inner_raw_in_frame,
               std::array<EdgeSpacing, kEdges>* outer, std::array<EdgeSpacing, kAxes>* inner,
               bool* minimal) {
  if (anyCulled<kEdges>(levels.outer)) return false;
  const Bounds bounds = boundsFor(spacing);

  std::array<float, kEdges> outer_level{};
  bool frame = false;
  for (size_t e = 0; e < kEdges; ++e) {
    outer_level[e] = roundIfInteger(clampLevel(levels.outer[e], bounds), spacing);
    frame = frame || outer_level[e] > kOddFrameThreshold;
  }
  if (inner_raw_in_frame) {
    for (size_t a = 0; a < kAxes; ++a) frame = frame || levels.inner[a] > kOddFrameThreshold;
  }
  Bounds inner_bounds = bounds;
  if (spacing == Spacing::kFractionalOdd && frame) inner_bounds.low = kOddFrameInsideMinimum;

  bool all_ones = true;
  for (size_t e = 0; e < kEdges; ++e) {
    const Fixed level = fxp::fromFloat(outer_level[e]);
    (*outer)[e] = makeEdgeSpacing(level, outerParity(outer_level[e], spacing));
    all_ones = all_ones && level == fxp::kOne;
  }
  for (size_t a = 0; a < kAxes; ++a) {
    const float inner_level = roundIfInteger(clampLevel(levels.inner[a], inner_bounds), spacing);
    const Fixed level = fxp::fromFloat(inner_level);
    const Parity parity = innerParity(inner_level, spacing);
    (*inner)[a] = makeEdgeSpacing(level, parity);
    // The inside needs at least one ring inside the outer one: an inside level of 1 gives
    // a degenerate transition ring (a single point or row) rather than no ring at all.
    const int minimum_points = parity == Parity::kOdd ? 4 : 3;
    (*inner)[a].point_count = std::max((*inner)[a].point_count, minimum_points);
    all_ones = all_ones && level == fxp::kOne;
  }
  // All levels 1 is special-cased for integer and odd spacings only; fractional_even
  // never reaches 1 (its minimum is 2).
  *minimal = all_ones && (hardwareInteger(spacing) || spacing == Spacing::kFractionalOdd);
  return true;
}

}  // namespace

TrianglePlan planTriangle(Spacing spacing, const Levels& levels) {
  TrianglePlan plan;
  std::array<EdgeSpacing, 1> inner{};
  plan.culled = !planRings(spacing, effectiveLevels(Domain::kTriangle, spacing, levels),
                           /*inner_raw_in_frame=*/false, &plan.outer, &inner, &plan.minimal);
  plan.inner = inner[0];
  return plan;
}

QuadPlan planQuad(Spacing spacing, const Levels& levels) {
  QuadPlan plan;
  plan.culled = !planRings(spacing, effectiveLevels(Domain::kQuad, spacing, levels),
                           /*inner_raw_in_frame=*/true, &plan.outer, &plan.inner, &plan.minimal);
  return plan;
}

// Isoline (D3D11.3 spec §11, isoline domain; Vulkan "Isoline Tessellation"): outer[0] is
// the line density, always rounded up to an integer; outer[1] is the per-line detail,
// which follows the spacing.
IsolinePlan planIsoline(Spacing spacing, const Levels& raw) {
  IsolinePlan plan;
  const Levels levels = effectiveLevels(Domain::kIsoline, spacing, raw);
  if (anyCulled<2>(levels.outer)) {
    plan.culled = true;
    return plan;
  }
  const float detail = roundIfInteger(clampLevel(levels.outer[1], boundsFor(spacing)), spacing);
  plan.detail = makeEdgeSpacing(fxp::fromFloat(detail), outerParity(detail, spacing));

  const float density = std::ceil(clampLevel(levels.outer[0], kIntegerBounds));
  plan.density = makeEdgeSpacing(fxp::fromFloat(density), outerParity(density, Spacing::kInteger));
  plan.line_count = plan.density.point_count - 1;
  return plan;
}

float maxLevel(Spacing spacing) { return boundsFor(spacing).high; }

}  // namespace tb::tess
