#include "harness/lod/transition_extents.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <utility>

namespace tb::lod {
namespace {

// The squared radius of the smallest circle around a triangle (u, v), rounded up to float:
// half its longest side where the triangle is right or obtuse, else its circumradius.
float enclosingCircle(const tess::DomainPoint& a, const tess::DomainPoint& b,
                      const tess::DomainPoint& c) {
  const auto squared = [](const tess::DomainPoint& p, const tess::DomainPoint& q) {
    const double du = double(p[0]) - q[0], dv = double(p[1]) - q[1];
    return du * du + dv * dv;
  };
  const double ab = squared(a, b), bc = squared(b, c), ca = squared(c, a);
  const double longest = std::max({ab, bc, ca});
  const double twice_area = std::fabs((double(b[0]) - a[0]) * (double(c[1]) - a[1]) -
                                      (double(c[0]) - a[0]) * (double(b[1]) - a[1]));
  double r2 = longest / 4;
  if (2 * longest < ab + bc + ca && twice_area > 0)
    r2 = ab * bc * ca / (twice_area * twice_area) / 4;
  const float rounded = float(r2 * (1 + 1e-9));
  return double(rounded) < r2 ? std::nextafter(rounded, 1.0f) : rounded;
}

// The widest triangle of one tessellation along u and v (a triangle's barycentric u and v:
// SurfacePatches::evaluate and curvatureBounds take the domain point as it is), and the
// largest smallest-enclosing-circle radius squared.
std::array<float, kTransitionAxes> widestTriangle(const tess::Tessellation& t) {
  std::array<float, kTransitionAxes> widest{0, 0, 0};
  for (const std::array<uint32_t, 3>& triangle : t.triangles) {
    widest[kTransitionCircle] = std::max(
        widest[kTransitionCircle],
        enclosingCircle(t.points[triangle[0]], t.points[triangle[1]], t.points[triangle[2]]));
    for (int axis = 0; axis < 2; ++axis) {
      float low = t.points[triangle[0]][axis], high = low;
      for (int k = 1; k < 3; ++k) {
        low = std::min(low, t.points[triangle[k]][axis]);
        high = std::max(high, t.points[triangle[k]][axis]);
      }
      widest[axis] = std::max(widest[axis], high - low);
    }
  }
  return widest;
}

// The longest segment of the v = 0 edge of a quad at level o (every edge's rule is the same).
float longestSegment(tess::Spacing spacing, uint32_t o) {
  tess::Levels levels;
  levels.outer = {1, float(o), 1, 1};
  const tess::Tessellation t = tess::tessellate(tess::Domain::kQuad, spacing, levels);
  std::vector<float> along;
  for (const tess::DomainPoint& p : t.points) {
    if (p[1] == 0.0f) along.push_back(p[0]);
  }
  std::sort(along.begin(), along.end());
  assert(along.size() >= 2 && along.front() == 0.0f && along.back() == 1.0f);
  float longest = 0;
  for (size_t k = 1; k < along.size(); ++k) longest = std::max(longest, along[k] - along[k - 1]);
  return longest;
}

std::vector<float> measureTable(tess::Domain domain, tess::Spacing spacing) {
  const uint32_t edges = domain == tess::Domain::kQuad ? 4 : 3;
  std::vector<float> table(transitionSegmentIndex(edges, kTransitionLevels) + 1, 0.0f);
  for (uint32_t o = 1; o <= kTransitionLevels; ++o) {
    table[transitionSegmentIndex(edges, o)] = longestSegment(spacing, o);
  }
  tbb::parallel_for(uint32_t(0), edges * kTransitionLevels, [&](uint32_t job) {
    const uint32_t e = job / kTransitionLevels, o = job % kTransitionLevels + 1;
    for (uint32_t n = 1; n <= kTransitionLevels; ++n) {
      tess::Levels levels;
      levels.outer = {float(n), float(n), float(n), edges == 4 ? float(n) : 0.0f};
      levels.outer[e] = float(o);
      levels.inner = {float(n), edges == 4 ? float(n) : 0.0f};
      const std::array<float, kTransitionAxes> widest =
          widestTriangle(tess::tessellate(domain, spacing, levels));
      for (uint32_t axis = 0; axis < kTransitionAxes; ++axis) {
        table[transitionIndex(e, axis, o, n)] = widest[axis];
      }
    }
  });
  return table;
}

}  // namespace

bool equalSegmentLevel(uint32_t level, tess::Spacing spacing) {
  switch (spacing) {
    case tess::Spacing::kPow2:
      return (level & (level - 1)) == 0;
    case tess::Spacing::kFractionalOdd:
      return level % 2 == 1;
    case tess::Spacing::kFractionalEven:
      return level % 2 == 0;
    case tess::Spacing::kInteger:
      break;
  }
  return true;
}

bool narrowEdgeLevel(uint32_t level, tess::Spacing spacing) {
  if (!equalSegmentLevel(level, spacing)) return false;
  switch (spacing) {
    case tess::Spacing::kInteger:  // 1, 2 and 2^k + 1, then the top
      return level <= 3 || level == 64 || ((level - 1) & (level - 2)) == 0;
    case tess::Spacing::kFractionalOdd:  // 1 and 2^k + 1, then the top
      return level == 1 || level == 63 || ((level - 1) & (level - 2)) == 0;
    case tess::Spacing::kFractionalEven:  // 2^k
    case tess::Spacing::kPow2:
      return (level & (level - 1)) == 0;
  }
  return true;
}

RingFactors ringFactors(tess::Domain domain) {
  if (domain == tess::Domain::kIsoline) {
    throw std::invalid_argument("ringFactors: the isoline domain has no triangles");
  }
  static std::mutex mutex;
  static std::map<tess::Domain, RingFactors> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  if (const auto it = cache.find(domain); it != cache.end()) return it->second;
  const bool quad = domain == tess::Domain::kQuad;
  RingFactors factors{0, 0, 0};
  for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kPow2,
                                tess::Spacing::kFractionalOdd, tess::Spacing::kFractionalEven}) {
    for (uint32_t o = 1; o <= kTransitionLevels; ++o) {
      if (!equalSegmentLevel(o, spacing) || float(o) > tess::maxLevel(spacing)) continue;
      tess::Levels levels;
      levels.outer = {float(o), float(o), float(o), quad ? float(o) : 0.0f};
      levels.inner = {float(o), quad ? float(o) : 0.0f};
      const std::array<float, kTransitionAxes> widest =
          widestTriangle(tess::tessellate(domain, spacing, levels));
      factors.u = std::max(factors.u, double(widest[0]) * o);
      factors.v = std::max(factors.v, double(widest[1]) * o);
      factors.circle = std::max(factors.circle, double(widest[kTransitionCircle]) * o * o);
    }
  }
  cache.emplace(domain, factors);
  return factors;
}

const std::vector<float>& transitionExtents(tess::Domain domain, tess::Spacing spacing) {
  if (domain == tess::Domain::kIsoline) {
    throw std::invalid_argument("transitionExtents: the isoline domain has no triangles");
  }
  static std::mutex mutex;
  static std::map<std::pair<tess::Domain, tess::Spacing>, std::unique_ptr<std::vector<float>>>
      tables;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<std::vector<float>>& table = tables[{domain, spacing}];
  if (!table) table = std::make_unique<std::vector<float>>(measureTable(domain, spacing));
  return *table;
}

}  // namespace tb::lod
