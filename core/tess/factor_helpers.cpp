#include "core/tess/factor_helpers.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

#include "core/tess/level_rules.h"

namespace tb::tess {
namespace {

enum class Reduction { kAverage, kMax, kMin };

constexpr float kFrameMinimum = 3.0f;

// D3D11 IEEE-754R min/max: a NaN second operand yields the first.
float d3dMin(float a, float b) { return std::isnan(b) ? a : (a < b ? a : b); }
float d3dMax(float a, float b) { return std::isnan(b) ? a : (a >= b ? a : b); }

// Raw edge factors below 1 (or NaN) count as 1 once the patch is known not to cull.
float cleanupFactor(float x) { return (std::isnan(x) || x < 1.0f) ? 1.0f : x; }
float cleanupScale(float x) { return (std::isnan(x) || x < 0.0f) ? 0.0f : std::min(x, 1.0f); }

// pow2: up to the next power of two by bumping the exponent when any mantissa bit is
// set (x >= 1 and finite here); integer: up to the next integer; fractional: unchanged.
float roundUpFactor(float x, Spacing spacing) {
  if (spacing == Spacing::kPow2) {
    constexpr uint32_t kMantissa = 0x007fffffu;
    constexpr uint32_t kExponent = 0x7f800000u;
    const auto bits = std::bit_cast<uint32_t>(x);
    if ((bits & kMantissa) == 0) return x;
    return std::bit_cast<float>((bits & kExponent) + (kMantissa + 1));
  }
  return spacing == Spacing::kInteger ? std::ceil(x) : x;
}

float clampFactor(float x, Spacing spacing) { return clampLevel(x, boundsFor(spacing)); }

// Left-to-right, so the float sum matches the HLSL layer's expression order.
float reduce(Reduction reduction, std::span<const float> edges) {
  float result = edges[0];
  for (size_t i = 1; i < edges.size(); ++i) {
    switch (reduction) {
      case Reduction::kAverage:
        result += edges[i];
        break;
      case Reduction::kMax:
        result = d3dMax(result, edges[i]);
        break;
      case Reduction::kMin:
        result = d3dMin(result, edges[i]);
        break;
    }
  }
  return reduction == Reduction::kAverage ? result / static_cast<float>(edges.size()) : result;
}

struct Inside {
  float rounded;
  float unrounded;
  bool odd;
};

// One inside factor from the edges that feed it. An odd inside factor below 3 would
// snap the first ring onto the edges, so it is recomputed without the scale from the
// average (or the maximum, for the Max helpers) of the edges, capped at 3.
Inside insideFactor(Spacing spacing, Reduction reduction, std::span<const float> edges,
                    float scale) {
  Inside in{};
  in.rounded = clampFactor(reduce(reduction, edges) * cleanupScale(scale), spacing);
  in.unrounded = in.rounded;
  if (hardwareInteger(spacing)) {
    in.rounded = roundUpFactor(in.rounded, spacing);
    in.odd = !(isEvenLevel(in.rounded) || in.rounded == 1.0f);
  } else {
    in.odd = spacing == Spacing::kFractionalOdd;
  }
  if (in.odd && in.rounded < kFrameMinimum) {
    const Reduction widen = reduction == Reduction::kMax ? Reduction::kMax : Reduction::kAverage;
    in.rounded = clampFactor(d3dMin(kFrameMinimum, reduce(widen, edges)), spacing);
    in.unrounded = in.rounded;
    if (spacing == Spacing::kInteger) {
      in.rounded = std::ceil(in.rounded);
      in.odd = !isEvenLevel(in.rounded);
    }
  }
  return in;
}

// Cleans the raw edges and writes the rounded, clamped edge levels. False if culled.
template <size_t kEdges>
bool processEdges(Spacing spacing, const std::array<float, kEdges>& raw,
                  std::array<float, kEdges>* cleaned, ProcessedFactors* out) {
  if (std::any_of(raw.begin(), raw.end(), [](float f) { return !(f > 0.0f); })) return false;
  for (size_t e = 0; e < kEdges; ++e) {
    (*cleaned)[e] = cleanupFactor(raw[e]);
    out->rounded.outer[e] = clampFactor(roundUpFactor((*cleaned)[e], spacing), spacing);
  }
  return true;
}

ProcessedFactors processTri(Spacing spacing, const std::array<float, 3>& raw, float scale,
                            Reduction reduction) {
  ProcessedFactors out;
  std::array<float, 3> edges{};
  if (!processEdges(spacing, raw, &edges, &out)) return ProcessedFactors{};
  const Inside in = insideFactor(spacing, reduction, edges, scale);
  out.rounded.inner[0] = in.rounded;
  out.unrounded_inner[0] = in.unrounded;
  return out;
}

// two_axis: Process2DQuad (each axis from its parallel edges) instead of ProcessQuad
// (both axes from all four edges, scale[0] only).
ProcessedFactors processQuad(Spacing spacing, const std::array<float, 4>& raw,
                             const std::array<float, 2>& scale, Reduction reduction,
                             bool two_axis) {
  ProcessedFactors out;
  std::array<float, 4> edges{};
  if (!processEdges(spacing, raw, &edges, &out)) return ProcessedFactors{};
  // Edges along u are v = 0 and v = 1 (indices 1, 3); along v are u = 0, u = 1 (0, 2).
  const std::array<float, 4> all{edges[1], edges[3], edges[0], edges[2]};
  if (!two_axis) {
    const Inside in = insideFactor(spacing, reduction, all, scale[0]);
    out.rounded.inner = {in.rounded, in.rounded};
    out.unrounded_inner = {in.unrounded, in.unrounded};
    return out;
  }
  const std::span<const float> along_u(all.data(), 2);
  const std::span<const float> along_v(all.data() + 2, 2);
  const std::array<Inside, 2> in{insideFactor(spacing, reduction, along_u, scale[0]),
                                 insideFactor(spacing, reduction, along_v, scale[1])};
  std::array<float, 2> level{in[0].rounded, in[1].rounded};
  // An odd axis below 3 is raised towards the other axis (at most to 3), so the first
  // ring comes in from every side as far as from the side with the larger factor.
  for (size_t axis = 0; axis < 2; ++axis) {
    out.unrounded_inner[axis] = in[axis].unrounded;
    const float other = level[1 - axis];
    if (in[axis].odd && level[axis] < kFrameMinimum && level[axis] < other) {
      level[axis] = d3dMin(other, kFrameMinimum);
      out.unrounded_inner[axis] = level[axis];
    }
  }
  out.rounded.inner = level;
  return out;
}

}  // namespace

ProcessedFactors processTriTessFactorsAvg(Spacing spacing, const std::array<float, 3>& raw_edges,
                                          float inside_scale) {
  return processTri(spacing, raw_edges, inside_scale, Reduction::kAverage);
}
ProcessedFactors processTriTessFactorsMax(Spacing spacing, const std::array<float, 3>& raw_edges,
                                          float inside_scale) {
  return processTri(spacing, raw_edges, inside_scale, Reduction::kMax);
}
ProcessedFactors processTriTessFactorsMin(Spacing spacing, const std::array<float, 3>& raw_edges,
                                          float inside_scale) {
  return processTri(spacing, raw_edges, inside_scale, Reduction::kMin);
}

ProcessedFactors processQuadTessFactorsAvg(Spacing spacing, const std::array<float, 4>& raw_edges,
                                           float inside_scale) {
  return processQuad(spacing, raw_edges, {inside_scale, 0}, Reduction::kAverage, false);
}
ProcessedFactors processQuadTessFactorsMax(Spacing spacing, const std::array<float, 4>& raw_edges,
                                           float inside_scale) {
  return processQuad(spacing, raw_edges, {inside_scale, 0}, Reduction::kMax, false);
}
ProcessedFactors processQuadTessFactorsMin(Spacing spacing, const std::array<float, 4>& raw_edges,
                                           float inside_scale) {
  return processQuad(spacing, raw_edges, {inside_scale, 0}, Reduction::kMin, false);
}

ProcessedFactors process2DQuadTessFactorsAvg(Spacing spacing, const std::array<float, 4>& raw_edges,
                                             const std::array<float, 2>& inside_scale) {
  return processQuad(spacing, raw_edges, inside_scale, Reduction::kAverage, true);
}
ProcessedFactors process2DQuadTessFactorsMax(Spacing spacing, const std::array<float, 4>& raw_edges,
                                             const std::array<float, 2>& inside_scale) {
  return processQuad(spacing, raw_edges, inside_scale, Reduction::kMax, true);
}
ProcessedFactors process2DQuadTessFactorsMin(Spacing spacing, const std::array<float, 4>& raw_edges,
                                             const std::array<float, 2>& inside_scale) {
  return processQuad(spacing, raw_edges, inside_scale, Reduction::kMin, true);
}

ProcessedFactors processIsolineTessFactors(Spacing spacing, float raw_detail, float raw_density) {
  ProcessedFactors out;
  if (!(raw_detail > 0.0f) || !(raw_density > 0.0f)) return out;
  const float detail = clampFactor(cleanupFactor(raw_detail), spacing);
  out.rounded.outer[1] = hardwareInteger(spacing) ? roundUpFactor(detail, spacing) : detail;
  out.rounded.outer[0] = std::ceil(clampLevel(cleanupFactor(raw_density), kIntegerBounds));
  return out;
}

Levels roundPow2Levels(Domain domain, const Levels& levels) {
  auto to_pow2 = [](float level) {
    return roundUpFactor(clampLevel(level, kIntegerBounds), Spacing::kPow2);
  };
  Levels out = levels;
  const size_t first_outer = domain == Domain::kIsoline ? 1 : 0;
  const size_t outer_count = domain == Domain::kTriangle ? 3 : (domain == Domain::kQuad ? 4 : 2);
  for (size_t e = first_outer; e < outer_count; ++e) {
    if (levels.outer[e] > 0.0f) out.outer[e] = to_pow2(levels.outer[e]);
  }
  const size_t inner_count = domain == Domain::kTriangle ? 1 : (domain == Domain::kQuad ? 2 : 0);
  for (size_t a = 0; a < inner_count; ++a) out.inner[a] = to_pow2(levels.inner[a]);
  return out;
}

}  // namespace tb::tess
