// CPU fixed-function tessellator that reproduces, bit for bit, what lavapipe
// (Mesa's copy of the D3D11 reference tessellator) emits. Written from the
// Vulkan specification's tessellation chapter and the D3D11 functional
// specification; see tessellator.cpp for the rules and where each comes from.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tb::tess {

enum class Domain { kTriangle, kQuad, kIsoline };

// kPow2 is a D3D11 HLSL partitioning: the HLSL layer rounds levels up to a power
// of two and then tessellates with integer spacing. Vulkan has no such mode; the
// GPU path rounds in the TCS (see roundPow2Levels).
enum class Spacing { kInteger, kPow2, kFractionalOdd, kFractionalEven };

// Levels exactly as written to gl_TessLevelOuter / gl_TessLevelInner.
// Triangle: outer[0..2], inner[0]. Quad: outer[0..3], inner[0..1].
// Isoline: outer[0] = line count (density), outer[1] = segments per line (detail).
struct Levels {
  std::array<float, 4> outer{1, 1, 1, 1};
  std::array<float, 2> inner{1, 1};
};

// The levels as float bits (outer 0..3, inner 0..1): a key under which equal levels share
// one tessellation, with -0 and each NaN kept distinct as the tessellator sees them.
using LevelsBits = std::array<uint32_t, 6>;
inline LevelsBits levelsBits(const Levels& levels) {
  LevelsBits bits{};
  for (int i = 0; i < 4; ++i) bits[i] = std::bit_cast<uint32_t>(levels.outer[i]);
  for (int i = 0; i < 2; ++i) bits[4 + i] = std::bit_cast<uint32_t>(levels.inner[i]);
  return bits;
}

// One domain point as the TES sees gl_TessCoord. Triangle: (u, v, w) barycentric;
// quad and isoline: (u, v, 0). Every coordinate is a multiple of 2^-16.
using DomainPoint = std::array<float, 3>;

struct Tessellation {
  bool culled = false;                             // any relevant outer level <= 0 or NaN
  std::vector<DomainPoint> points;                 // unique domain points (= TES invocations)
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into points (tri/quad domains)
  std::vector<std::array<uint32_t, 2>> lines;      // indices into points (isoline domain)
};

struct Options {
  bool point_mode = false;  // primitives are not emitted (points only)
  bool ccw = true;          // output winding of triangles, as layout(ccw)/layout(cw)
};

Tessellation tessellate(Domain domain, Spacing spacing, const Levels& levels,
                        const Options& options = {});

// The largest level the spacing takes (D3D11.3 §11): 63 for fractional_odd, else 64. Higher
// levels (and +inf) are clamped to it.
float maxLevel(Spacing spacing);

// Closed-form counts for uniform integer level n >= 1 (tested against tessellate()).
uint64_t quadPointCount(uint32_t n);         // (n+1)^2
uint64_t quadTriangleCount(uint32_t n);      // 2 n^2
uint64_t trianglePointCount(uint32_t n);     // odd n: 3((n+1)/2)^2; even n: 3(n/2)(n/2+1)+1
uint64_t triangleTriangleCount(uint32_t n);  // floor(3 n^2 / 2)

std::string_view toString(Domain d);
std::string_view toString(Spacing s);
// Parse "tri|quad|isoline" and "integer|pow2|fractional_odd|fractional_even";
// return false on an unknown name.
bool parseDomain(std::string_view name, Domain* out);
bool parseSpacing(std::string_view name, Spacing* out);

}  // namespace tb::tess
