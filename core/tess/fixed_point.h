// 16.16 fixed-point numbers as the D3D11 fixed-function tessellator uses them
// (D3D11.3 functional spec §11 "Tessellator"; lavapipe runs Microsoft's reference
// implementation of that chapter). Levels are converted to fixed point before any
// placement, so every domain coordinate is a multiple of 2^-16 and converts to float
// exactly: the tessellator never produces i/n in float.
#pragma once

#include <bit>
#include <cassert>
#include <cmath>
#include <cstdint>

namespace tb::tess::fxp {

using Fixed = uint32_t;  // unsigned 16.16; all arithmetic wraps mod 2^32 like the reference

inline constexpr int kFractionBits = 16;
inline constexpr Fixed kOne = Fixed{1} << kFractionBits;
inline constexpr Fixed kHalf = kOne / 2;
inline constexpr Fixed kFractionMask = kOne - 1;
inline constexpr Fixed kIntegerMask = 0x7fff0000u;  // 15 integer bits
// 1/3 and 2/3 truncated (not rounded) to 16 bits: the triangle domain's centre and the
// barycentric step between rings are defined with these exact values.
inline constexpr Fixed kOneThird = 0x5555u;
inline constexpr Fixed kTwoThirds = 0xaaaau;

// Float to unsigned 16.16 with round-half-to-even on the dropped bits. NaN and any
// negative value give 0, values of 2^15 or more saturate (D3D data conversion rules,
// "Fixed Point Integer Conversion": round-to-nearest-even; 15 integer bits here).
inline Fixed fromFloat(float x) {
  if (std::isnan(x) || !(x > 0.0f)) return 0;
  if (x >= 32768.0f) return ~Fixed{0};
  // x * 2^16 is exact in double (24-bit mantissa, exponent within range).
  const double scaled = static_cast<double>(x) * 65536.0;
  const double whole = std::floor(scaled);
  const double dropped = scaled - whole;
  Fixed result = static_cast<Fixed>(whole);
  if (dropped > 0.5 || (dropped == 0.5 && (result & 1u) != 0)) ++result;
  return result;
}

// Exact for every value the tessellator produces (at most 2^22, so 23 significant bits).
constexpr float toFloat(Fixed f) { return static_cast<float>(f) * (1.0f / 65536.0f); }

constexpr Fixed ceil(Fixed f) { return (f & kFractionMask) ? (f & kIntegerMask) + kOne : f; }
constexpr Fixed floor(Fixed f) { return f & kIntegerMask; }
constexpr int toInt(Fixed f) { return static_cast<int>(f >> kFractionBits); }

// 1/n in 16.16 rounded to nearest, ties up; n is a segment count in [1, 64]. The
// reference tessellator keeps these in a table, and lavapipe's coordinates inherit
// its rounding (e.g. 1/6 = 0x2aab, 1/34 = 0x788).
constexpr Fixed reciprocal(int n) {
  assert(n >= 1 && n <= 64);
  return static_cast<Fixed>((2 * kOne + static_cast<Fixed>(n)) / (2 * static_cast<Fixed>(n)));
}

// Clears the highest set bit (0 stays 0): the split-point rule of the fractional
// placement (see edge_spacing.cpp).
constexpr int removeHighestBit(int value) {
  assert(value >= 0);
  const auto bits = static_cast<unsigned>(value);
  return static_cast<int>(bits - std::bit_floor(bits));
}

}  // namespace tb::tess::fxp
