// Level ranges and the clamp shared by the hardware rules (patch_plan.cpp) and the HLSL
// helper rules (factor_helpers.cpp). Internal to tb_tess.
#pragma once

#include "core/tess/tessellator.h"

namespace tb::tess {

struct Bounds {
  float low;
  float high;
};

// D3D11.3 functional spec §11 (TessFactor ranges): integer and pow2 [1, 64],
// fractional_odd [1, 63], fractional_even [2, 64]. The isoline density is always [1, 64].
inline constexpr Bounds kIntegerBounds{1.0f, 64.0f};
inline constexpr Bounds kOddBounds{1.0f, 63.0f};
inline constexpr Bounds kEvenBounds{2.0f, 64.0f};

// Integer and pow2 are the same to the hardware: pow2 is rounded before it gets there.
inline bool hardwareInteger(Spacing spacing) {
  return spacing == Spacing::kInteger || spacing == Spacing::kPow2;
}

inline Bounds boundsFor(Spacing spacing) {
  switch (spacing) {
    case Spacing::kFractionalOdd:
      return kOddBounds;
    case Spacing::kFractionalEven:
      return kEvenBounds;
    case Spacing::kInteger:
    case Spacing::kPow2:
      break;
  }
  return kIntegerBounds;
}

// min(high, max(low, x)) with the D3D11 IEEE-754R min/max (D3D11.3 spec, floating-point
// rules): NaN, and anything not above low (denormals included), becomes low.
inline float clampLevel(float x, Bounds bounds) {
  const float at_least_low = x > bounds.low ? x : bounds.low;
  return bounds.high < at_least_low ? bounds.high : at_least_low;
}

// Parity of a rounded level, by truncation to int as the reference does.
inline bool isEvenLevel(float level) { return (static_cast<int>(level) & 1) == 0; }

}  // namespace tb::tess
