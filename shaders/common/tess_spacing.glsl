// The compute tessellator's level rules and edge placement: a GLSL port of
// core/tess/fixed_point.h, edge_spacing.cpp, level_rules.h, factor_helpers.cpp
// (roundPow2Levels) and patch_plan.cpp, in the same uint 16.16 arithmetic (wrapping mod
// 2^32 like the D3D11 reference tessellator that lavapipe runs). Floats appear only where
// the CPU model works on the shader-written float levels (clamp, ceil, the pow2 bit trick)
// and in the exact float -> 16.16 conversion. Tests: tests/gpu/compute_tessellator_test.cpp.
#ifndef TB_TESS_SPACING_GLSL
#define TB_TESS_SPACING_GLSL

// The tests' broken control, per patch: the float -> 16.16 conversion rounds any dropped
// bits up instead of rounding half to even.
bool g_tb_rounding_up_control = false;

// Domain and spacing codes: the order of tb::tess::Domain and tb::tess::Spacing.
const uint kTbDomainTriangle = 0u;
const uint kTbDomainQuad = 1u;
const uint kTbDomainIsoline = 2u;
const uint kTbSpacingInteger = 0u;
const uint kTbSpacingPow2 = 1u;
const uint kTbSpacingFractionalOdd = 2u;
const uint kTbSpacingFractionalEven = 3u;

const uint kFxOne = 0x10000u;
const uint kFxHalf = 0x8000u;
const uint kFxFractionMask = 0xffffu;
const uint kFxIntegerMask = 0x7fff0000u;
const uint kFxOneThird = 0x5555u;
const uint kFxTwoThirds = 0xaaaau;

// On the float bits, so that no device flush of denormals or NaN handling can differ
// from the CPU model's IEEE comparisons.
bool tbIsNan(float x) { return (floatBitsToUint(x) & 0x7fffffffu) > 0x7f800000u; }
// x > 0 exactly as IEEE compares (denormals and +inf included, NaN and -0 not).
bool tbAboveZero(float x) {
  const uint bits = floatBitsToUint(x);
  return bits != 0u && bits <= 0x7f800000u;
}

// fixed_point.h fromFloat: round half to even on the dropped bits; NaN and x <= 0 give 0,
// x >= 2^15 saturates. x * 2^16 and its fraction are exact in float.
uint tbFxFromFloat(float x) {
  if (!tbAboveZero(x)) return 0u;
  if (x >= 32768.0) return 0xffffffffu;
  const float scaled = x * 65536.0;
  const float whole = floor(scaled);
  const float dropped = scaled - whole;
  uint result = uint(whole);
  if (g_tb_rounding_up_control) return dropped > 0.0 ? result + 1u : result;
  if (dropped > 0.5 || (dropped == 0.5 && (result & 1u) != 0u)) ++result;
  return result;
}

uint tbFxCeil(uint f) { return (f & kFxFractionMask) != 0u ? (f & kFxIntegerMask) + kFxOne : f; }
uint tbFxFloor(uint f) { return f & kFxIntegerMask; }
int tbFxToInt(uint f) { return int(f >> 16); }
// 1/n in 16.16, rounded to nearest with ties up (the reference tessellator's table).
uint tbFxReciprocal(int n) { return (2u * kFxOne + uint(n)) / (2u * uint(n)); }
// Clears the highest set bit of value >= 0.
int tbRemoveHighestBit(int value) { return value == 0 ? 0 : value & ~(1 << findMSB(value)); }

// level_rules.h: min(high, max(low, x)) with D3D11 min/max, NaN -> low.
float tbClampLevel(float x, float low, float high) {
  const float at_least_low = (!tbIsNan(x) && x > low) ? x : low;
  return high < at_least_low ? high : at_least_low;
}
float tbLowBound(uint spacing) { return spacing == kTbSpacingFractionalEven ? 2.0 : 1.0; }
float tbHighBound(uint spacing) { return spacing == kTbSpacingFractionalOdd ? 63.0 : 64.0; }
bool tbHardwareInteger(uint spacing) { return spacing <= kTbSpacingPow2; }
bool tbIsEvenLevel(float level) { return (int(level) & 1) == 0; }
float tbRoundIfInteger(float level, uint spacing) {
  return tbHardwareInteger(spacing) ? ceil(level) : level;
}

// factor_helpers.cpp roundUpFactor(pow2) after the [1, 64] clamp: up to a power of two by
// the exponent bits.
float tbRoundPow2(float level) {
  const uint bits = floatBitsToUint(tbClampLevel(level, 1.0, 64.0));
  if ((bits & 0x007fffffu) == 0u) return uintBitsToFloat(bits);
  return uintBitsToFloat((bits & 0x7f800000u) + 0x00800000u);
}

// edge_spacing.h EdgeSpacing: everything to place the points of one processed level.
struct TbEdgeSpacing {
  bool odd;
  int point_count;   // points on the edge, both ends included
  int half_points;   // points on one half before the middle
  int split_point;   // index past which the floor layout lags one point behind
  uint half_fraction;
  uint inv_floor_segments;
  uint inv_ceil_segments;
};

// edge_spacing.cpp makeEdgeSpacing; level in 16.16, clamped and (integer) rounded.
TbEdgeSpacing tbMakeEdgeSpacing(uint level, bool odd) {
  TbEdgeSpacing s;
  s.odd = odd;
  const uint half_level_raw = (level + 1u) / 2u;
  s.point_count = odd ? tbFxToInt(tbFxCeil(kFxHalf + half_level_raw) * 2u)
                      : tbFxToInt(tbFxCeil(half_level_raw) * 2u) + 1;
  uint half_level = half_level_raw;
  if (odd || half_level == kFxHalf) half_level += kFxHalf;
  const uint floor_half = tbFxFloor(half_level);
  const uint ceil_half = tbFxCeil(half_level);
  s.half_fraction = half_level - floor_half;
  s.half_points = tbFxToInt(ceil_half);
  if (ceil_half == floor_half) {
    s.split_point = s.half_points + 1;
  } else if (odd) {
    s.split_point =
        floor_half == kFxOne ? 0 : (tbRemoveHighestBit(tbFxToInt(floor_half) - 1) << 1) + 1;
  } else {
    s.split_point = (tbRemoveHighestBit(tbFxToInt(floor_half)) << 1) + 1;
  }
  int floor_segments = tbFxToInt(floor_half * 2u);
  int ceil_segments = tbFxToInt(ceil_half * 2u);
  if (odd) {
    --floor_segments;
    --ceil_segments;
  }
  s.inv_floor_segments = tbFxReciprocal(floor_segments);
  s.inv_ceil_segments = tbFxReciprocal(ceil_segments);
  return s;
}

// edge_spacing.cpp placePoint: mirrored halves, exact 0.5 middle, 32-bit blend.
uint tbPlacePoint(TbEdgeSpacing s, int index) {
  bool mirrored = false;
  int point = index;
  if (point >= s.half_points) {
    point = 2 * s.half_points - point - (s.odd ? 1 : 0);
    mirrored = true;
  }
  if (point == s.half_points) return kFxHalf;
  const uint on_ceil = uint(point);
  const uint on_floor = point > s.split_point ? on_ceil - 1u : on_ceil;
  const uint at_floor = on_floor * s.inv_floor_segments;
  const uint at_ceil = on_ceil * s.inv_ceil_segments;
  uint location = at_floor * (kFxOne - s.half_fraction) + at_ceil * s.half_fraction;
  location = (location + kFxHalf) >> 16;
  return mirrored ? kFxOne - location : location;
}

// patch_plan.cpp: triangle and quad plans in one (a triangle uses outer 0..2, inner 0).
// Named fields, not arrays: no dynamically indexed private array (scratch memory on some
// drivers) is needed.
struct TbRingPlan {
  bool minimal;  // every level 1: one triangle (tri) or two (quad), no rings
  TbEdgeSpacing outer0, outer1, outer2, outer3;  // edges in gl_TessLevelOuter order
  TbEdgeSpacing inner0, inner1;                  // along u, along v
};

TbEdgeSpacing tbPlanOuter(TbRingPlan plan, int e) {
  if (e == 0) return plan.outer0;
  if (e == 1) return plan.outer1;
  return e == 2 ? plan.outer2 : plan.outer3;
}
TbEdgeSpacing tbPlanInner(TbRingPlan plan, int axis) {
  return axis == 0 ? plan.inner0 : plan.inner1;
}

struct TbIsolinePlan {
  int line_count;
  TbEdgeSpacing density;
  TbEdgeSpacing detail;
};

bool tbOuterOdd(float level, uint spacing) {
  if (!tbHardwareInteger(spacing)) return spacing != kTbSpacingFractionalEven;
  return !tbIsEvenLevel(level);
}
bool tbInnerOdd(float level, uint spacing) {
  if (!tbHardwareInteger(spacing)) return spacing != kTbSpacingFractionalEven;
  return !(tbIsEvenLevel(level) || level == 1.0);
}

// patch_plan.cpp effectiveLevels + roundPow2Levels: pow2 rounds the used levels (outer ones
// only where they do not cull; the isoline density never) before the integer rules.
void tbPow2Levels(uint domain, inout vec4 outer, inout vec2 inner) {
  const uint first_outer = domain == kTbDomainIsoline ? 1u : 0u;
  const uint outer_count = domain == kTbDomainTriangle ? 3u : (domain == kTbDomainQuad ? 4u : 2u);
  for (uint e = first_outer; e < outer_count; ++e) {
    if (tbAboveZero(outer[e])) outer[e] = tbRoundPow2(outer[e]);
  }
  const uint inner_count = domain == kTbDomainTriangle ? 1u : (domain == kTbDomainQuad ? 2u : 0u);
  for (uint a = 0u; a < inner_count; ++a) inner[a] = tbRoundPow2(inner[a]);
}

// patch_plan.cpp planRings for a triangle (3 edges, 1 axis) or a quad (4, 2; its raw inside
// levels count towards the odd picture frame). The levels are pow2-rounded, not culled.
TbRingPlan tbPlanRings(uint spacing, vec4 outer, vec2 inner, bool quad) {
  const float kOddFrameThreshold = 1.0 + 1.0 / 131072.0;
  const float kOddFrameInsideMinimum = 1.0 + 1.0 / 65536.0;
  const int edges = quad ? 4 : 3, axes = quad ? 2 : 1;
  const float low = tbLowBound(spacing), high = tbHighBound(spacing);
  vec4 outer_level = vec4(1.0);
  bool frame = false;
  for (int e = 0; e < edges; ++e) {
    outer_level[e] = tbRoundIfInteger(tbClampLevel(outer[e], low, high), spacing);
    frame = frame || outer_level[e] > kOddFrameThreshold;
  }
  if (quad) frame = frame || inner.x > kOddFrameThreshold || inner.y > kOddFrameThreshold;
  const float inner_low =
      (spacing == kTbSpacingFractionalOdd && frame) ? kOddFrameInsideMinimum : low;
  bool all_ones = true;
  TbEdgeSpacing s[6];
  for (int e = 0; e < edges; ++e) {
    const uint level = tbFxFromFloat(outer_level[e]);
    s[e] = tbMakeEdgeSpacing(level, tbOuterOdd(outer_level[e], spacing));
    all_ones = all_ones && level == kFxOne;
  }
  for (int a = 0; a < axes; ++a) {
    const float inner_level = tbRoundIfInteger(tbClampLevel(inner[a], inner_low, high), spacing);
    const uint level = tbFxFromFloat(inner_level);
    const bool odd = tbInnerOdd(inner_level, spacing);
    s[4 + a] = tbMakeEdgeSpacing(level, odd);
    s[4 + a].point_count = max(s[4 + a].point_count, odd ? 4 : 3);
    all_ones = all_ones && level == kFxOne;
  }
  const bool minimal =
      all_ones && (tbHardwareInteger(spacing) || spacing == kTbSpacingFractionalOdd);
  return TbRingPlan(minimal, s[0], s[1], s[2], s[3], s[4], s[5]);
}

// patch_plan.cpp planIsoline: detail per the spacing, density always integer in [1, 64].
TbIsolinePlan tbPlanIsoline(uint spacing, vec4 outer) {
  TbIsolinePlan plan;
  const float detail =
      tbRoundIfInteger(tbClampLevel(outer[1], tbLowBound(spacing), tbHighBound(spacing)), spacing);
  plan.detail = tbMakeEdgeSpacing(tbFxFromFloat(detail), tbOuterOdd(detail, spacing));
  const float density = ceil(tbClampLevel(outer[0], 1.0, 64.0));
  plan.density = tbMakeEdgeSpacing(tbFxFromFloat(density), !tbIsEvenLevel(density));
  plan.line_count = plan.density.point_count - 1;
  return plan;
}

#endif
