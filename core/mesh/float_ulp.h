// Distance between floats in units in the last place: the one definition the crack
// measure and every GPU-against-CPU comparison use.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>

#include "core/mesh/vec.h"

namespace tb::mesh {

// The count of representable floats between a and b (+0 and -0 are 0 apart; best case
// 0, 1 is one rounding step). Meaningful for finite values.
inline uint64_t ulpDistance(float a, float b) {
  auto ordered = [](float f) {
    const uint32_t bits = std::bit_cast<uint32_t>(f);
    return (bits & 0x80000000u) ? -int64_t(bits & 0x7fffffffu) : int64_t(bits);
  };
  const int64_t d = ordered(a) - ordered(b);
  return uint64_t(d < 0 ? -d : d);
}

// The largest component distance of two float vectors.
inline uint64_t maxUlpDistance(const Vec3f& a, const Vec3f& b) {
  return std::max({ulpDistance(a.x, b.x), ulpDistance(a.y, b.y), ulpDistance(a.z, b.z)});
}

}  // namespace tb::mesh
