// The tessellator's transition extents (harness/lod/transition_extents.h), which error_bound's
// inside level is chosen against: the table, built from one unequal edge at a time, covers
// every triangle of a tessellation whose edges all differ (the corner triangles between two
// unequal edges included), and a regular grid's extents (what a bound on an n x n grid
// assumes) do not.
#include "harness/lod/transition_extents.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "core/tess/tessellator.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using lod::kTransitionCircle;
using lod::transitionIndex;

// The widest triangle of `t` along u, v and its largest enclosing circle's squared radius.
std::array<double, 3> widest(const tess::Tessellation& t) {
  std::array<double, 3> out{0, 0, 0};
  for (const auto& tri : t.triangles) {
    const tess::DomainPoint &a = t.points[tri[0]], &b = t.points[tri[1]], &c = t.points[tri[2]];
    for (int axis = 0; axis < 2; ++axis) {
      const double low = std::min({a[axis], b[axis], c[axis]});
      const double high = std::max({a[axis], b[axis], c[axis]});
      out[axis] = std::max(out[axis], high - low);
    }
    const auto sq = [](const tess::DomainPoint& p, const tess::DomainPoint& q) {
      return (double(p[0]) - q[0]) * (double(p[0]) - q[0]) +
             (double(p[1]) - q[1]) * (double(p[1]) - q[1]);
    };
    const double ab = sq(a, b), bc = sq(b, c), ca = sq(c, a), longest = std::max({ab, bc, ca});
    const double area2 = std::fabs((double(b[0]) - a[0]) * (double(c[1]) - a[1]) -
                                   (double(c[0]) - a[0]) * (double(b[1]) - a[1]));
    const bool obtuse = 2 * longest >= ab + bc + ca || area2 == 0;
    out[2] = std::max(out[2], obtuse ? longest / 4 : ab * bc * ca / (area2 * area2) / 4);
  }
  return out;
}

struct Coverage {
  size_t configs = 0, within = 0, regular_exceeded = 0;
};

// Random configurations of whole levels at which the spacing's segments are equal: every edge
// its own level, one inside level.
Coverage sweep(tess::Domain domain, tess::Spacing spacing, size_t configs) {
  const uint32_t edges = domain == tess::Domain::kQuad ? 4 : 3;
  const std::vector<float>& table = lod::transitionExtents(domain, spacing);
  std::mt19937 random(7);
  const auto top = uint32_t(tess::maxLevel(spacing));
  std::uniform_int_distribution<uint32_t> level(1, top);
  auto draw = [&] {
    uint32_t x = level(random);
    while (!lod::equalSegmentLevel(x, spacing)) x = level(random);
    return x;
  };
  Coverage out;
  for (size_t k = 0; k < configs; ++k) {
    std::array<uint32_t, 4> outer{};
    const uint32_t n = draw();
    // Edges near the inside level (the policy's usual case) and anywhere.
    for (uint32_t e = 0; e < edges; ++e) {
      outer[e] = k % 2 == 0 ? draw() : std::clamp<uint32_t>(n + level(random) % 9 - 4, 1, top);
      while (!lod::equalSegmentLevel(outer[e], spacing)) ++outer[e];
      outer[e] = std::min(outer[e], top);
    }
    tess::Levels levels;
    for (uint32_t e = 0; e < edges; ++e) levels.outer[e] = float(outer[e]);
    if (edges == 3) levels.outer[3] = 0;
    levels.inner = {float(n), edges == 4 ? float(n) : 0.0f};
    const std::array<double, 3> actual = widest(tess::tessellate(domain, spacing, levels));
    std::array<double, 3> bound{0, 0, 0};
    for (uint32_t e = 0; e < edges; ++e) {
      for (uint32_t axis = 0; axis < 3; ++axis) {
        bound[axis] = std::max(bound[axis], double(table[transitionIndex(e, axis, outer[e], n)]));
      }
    }
    ++out.configs;
    const bool within = actual[0] <= bound[0] && actual[1] <= bound[1] && actual[2] <= bound[2];
    out.within += within ? 1 : 0;
    EXPECT_TRUE(within) << tess::toString(domain) << " " << tess::toString(spacing) << " outer ("
                        << outer[0] << " " << outer[1] << " " << outer[2] << " " << outer[3]
                        << ") inner " << n << ": widest " << actual[0] << " " << actual[1] << " "
                        << actual[2] << " against " << bound[0] << " " << bound[1] << " "
                        << bound[2];
    // The control: a regular grid of the coarsest level present.
    const double coarsest = *std::min_element(outer.begin(), outer.begin() + edges) < n
                                ? *std::min_element(outer.begin(), outer.begin() + edges)
                                : n;
    out.regular_exceeded += actual[0] > 1.0 / coarsest + 1e-6 ? 1 : 0;
  }
  return out;
}

TEST(TransitionExtents, EveryTriangleOfUnequalLevelsIsWithinItsEdgesEntries) {
  for (tess::Domain domain : {tess::Domain::kQuad, tess::Domain::kTriangle}) {
    for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd}) {
      // Under a sanitizer a sliver of the configurations (the tables cost the most there).
      const Coverage c = sweep(domain, spacing, ::tb::testing::kUnderSanitizer ? 24 : 200);
      EXPECT_EQ(c.within, c.configs);
      // The regular grid's 1 / level, which a bound on an n x n grid assumes, is exceeded.
      EXPECT_GT(c.regular_exceeded, c.configs / 4)
          << tess::toString(domain) << " " << tess::toString(spacing);
      std::printf(
          "[transition] %s %s: %zu configurations within the table, the coarsest level's "
          "regular grid exceeded in %zu\n",
          std::string(tess::toString(domain)).c_str(), std::string(tess::toString(spacing)).c_str(),
          c.within, c.regular_exceeded);
    }
  }
}

TEST(TransitionExtents, RegularPatternsAndAKnownTransition) {
  const std::vector<float>& quad =
      lod::transitionExtents(tess::Domain::kQuad, tess::Spacing::kInteger);
  for (uint32_t n : {1u, 2u, 7u, 16u, 64u}) {
    EXPECT_NEAR(quad[transitionIndex(1, 0, n, n)] * n, 1.0, 1e-3) << n;
    EXPECT_NEAR(quad[transitionIndex(1, kTransitionCircle, n, n)] * n * n, 0.5, 1e-3) << n;
    EXPECT_NEAR(quad[lod::transitionSegmentIndex(4, n)] * n, 1.0, 1e-3) << n;  // 16-bit fixed point
  }
  // Edge 32 stitched to an inside of 44: the first ring's triangles about 3.45 segments wide.
  EXPECT_GT(quad[transitionIndex(1, 0, 32, 44)] * 32, 3.4);
  const std::vector<float>& tri =
      lod::transitionExtents(tess::Domain::kTriangle, tess::Spacing::kInteger);
  EXPECT_NEAR(tri[transitionIndex(0, 0, 13, 13)] * 13, 4.0 / 3.0, 1e-2);  // the rings' spacing
  const std::vector<float>& odd =
      lod::transitionExtents(tess::Domain::kQuad, tess::Spacing::kFractionalOdd);
  EXPECT_NEAR(odd[lod::transitionSegmentIndex(4, 2)], 2.0 / 3.0, 1e-4);  // level 2's middle segment
  const lod::RingFactors ring = lod::ringFactors(tess::Domain::kTriangle);
  EXPECT_NEAR(ring.u, 4.0 / 3.0, 0.03);  // fractional levels' rings a little wider
}

}  // namespace
}  // namespace tb
