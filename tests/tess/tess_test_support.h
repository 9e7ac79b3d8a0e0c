// Helpers shared by the tb::tess tests: level generators and geometric checks.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/mesh/fnv1a.h"
#include "core/tess/tessellator.h"

namespace tb::tess::testing {

inline constexpr std::array<Domain, 3> kDomains{Domain::kTriangle, Domain::kQuad, Domain::kIsoline};
inline constexpr std::array<Spacing, 4> kSpacings{
    Spacing::kInteger, Spacing::kPow2, Spacing::kFractionalOdd, Spacing::kFractionalEven};

inline Levels uniformLevels(float level) {
  Levels l;
  l.outer = {level, level, level, level};
  l.inner = {level, level};
  return l;
}

// Random levels in [low, high] for every slot (deterministic per seed).
inline Levels randomLevels(std::mt19937& rng, float low, float high) {
  std::uniform_real_distribution<float> dist(low, high);
  Levels l;
  for (float& o : l.outer) o = dist(rng);
  for (float& i : l.inner) i = dist(rng);
  return l;
}

inline bool isMultipleOf2To16(float x) {
  const double scaled = static_cast<double>(x) * 65536.0;
  return scaled == std::floor(scaled);
}

// Twice the signed area of a triangle in the (u, v) plane, v up; exact in double for
// coordinates that are multiples of 2^-16.
inline double doubleSignedArea(const DomainPoint& a, const DomainPoint& b, const DomainPoint& c) {
  const double abu = double(b[0]) - a[0], abv = double(b[1]) - a[1];
  const double acu = double(c[0]) - a[0], acv = double(c[1]) - a[1];
  return abu * acv - abv * acu;
}

inline std::vector<double> doubleAreas(const Tessellation& t) {
  std::vector<double> areas;
  for (const auto& tri : t.triangles) {
    areas.push_back(doubleSignedArea(t.points[tri[0]], t.points[tri[1]], t.points[tri[2]]));
  }
  return areas;
}

// The parameters along one boundary edge, read from the points lying on it: `fixed` is
// the coordinate held at `value` (0 = u, 1 = v, 2 = w), `along` the one that varies.
inline std::vector<float> edgeParameters(const Tessellation& t, int fixed, float value, int along) {
  std::vector<float> params;
  for (const DomainPoint& p : t.points) {
    if (p[fixed] == value) params.push_back(p[along]);
  }
  std::sort(params.begin(), params.end());
  return params;
}

// FNV-1a over the point bits (u, v, w), a separator, then each primitive's vertices as
// (u, v) bits: the same digest the lavapipe capture was reduced to.
inline uint64_t outputDigest(const Tessellation& t) {
  uint64_t h = mesh::kFnv1aOffsetBasis;
  auto mix_bits = [&h](uint32_t x) { h = mesh::fnv1aWord(h, x, 4); };
  auto mix = [&](float f) { mix_bits(std::bit_cast<uint32_t>(f)); };
  for (const DomainPoint& p : t.points) {
    for (float c : p) mix(c);
  }
  mix_bits(0xffffffffu);
  auto mix_vertex = [&](uint32_t index) {
    mix(t.points[index][0]);
    mix(t.points[index][1]);
  };
  for (const auto& tri : t.triangles) {
    for (uint32_t index : tri) mix_vertex(index);
  }
  for (const auto& line : t.lines) {
    for (uint32_t index : line) mix_vertex(index);
  }
  return h;
}

}  // namespace tb::tess::testing
