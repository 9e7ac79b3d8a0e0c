// The HLSL Process*TessFactors* helpers and roundPow2Levels against hand-computed values
// (oracle: the HLSL intrinsic reference pages' rules: edge rounding per partitioning,
// inside = avg/max/min reduction times InsideScale, clamped then rounded, and the odd
// "at least 3" picture-frame rule). Each expectation shows its arithmetic.
#include "core/tess/factor_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tb::tess {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(TessFactorHelpers, TriangleReductions) {
  // Integer: edges ceil -> 1, 2, 4; inside (1 + 2 + 4) / 3 = 2.333 -> 3.
  ProcessedFactors f = processTriTessFactorsAvg(Spacing::kInteger, {1.0f, 2.0f, 4.0f}, 1.0f);
  EXPECT_EQ(f.rounded.outer, (std::array<float, 4>{1, 2, 4, 0}));
  EXPECT_EQ(f.rounded.inner[0], 3.0f);
  EXPECT_EQ(f.unrounded_inner[0], 7.0f / 3.0f);

  // Max with scale 0.5: edges 2, 3, 8; inside 7.2 * 0.5 = 3.6 -> 4.
  f = processTriTessFactorsMax(Spacing::kInteger, {1.5f, 2.5f, 7.2f}, 0.5f);
  EXPECT_EQ(f.rounded.outer, (std::array<float, 4>{2, 3, 8, 0}));
  EXPECT_EQ(f.unrounded_inner[0], 7.2f * 0.5f);
  EXPECT_EQ(f.rounded.inner[0], 4.0f);

  // fractional_odd Min: min 2.5 is odd and < 3, so the frame rule takes
  // min(3, average 5.5) = 3.
  f = processTriTessFactorsMin(Spacing::kFractionalOdd, {2.5f, 5.0f, 9.0f}, 1.0f);
  EXPECT_EQ(f.rounded.outer, (std::array<float, 4>{2.5f, 5.0f, 9.0f, 0}));
  EXPECT_EQ(f.rounded.inner[0], 3.0f);
  EXPECT_EQ(f.unrounded_inner[0], 3.0f);

  // pow2: edges 3 -> 4, 5 -> 8, 17 -> 32; inside 25 / 3 = 8.33 -> 16.
  f = processTriTessFactorsAvg(Spacing::kPow2, {3.0f, 5.0f, 17.0f}, 1.0f);
  EXPECT_EQ(f.rounded.outer, (std::array<float, 4>{4, 8, 32, 0}));
  EXPECT_EQ(f.rounded.inner[0], 16.0f);

  // fractional_even: raw 0.5 counts as 1 and clamps to 2; scale > 1 counts as 1;
  // edges above 64 clamp.
  f = processTriTessFactorsAvg(Spacing::kFractionalEven, {0.5f, 1.0f, 100.0f}, 4.0f);
  EXPECT_EQ(f.rounded.outer, (std::array<float, 4>{2, 2, 64, 0}));
  EXPECT_EQ(f.rounded.inner[0], 34.0f);  // (1 + 1 + 100) / 3
}

TEST(TessFactorHelpers, QuadOneAxisReductions) {
  // (v0 + v1 + u0 + u1) / 4 = (2 + 4 + 1 + 3) / 4 = 2.5 -> 3 on both axes.
  ProcessedFactors f = processQuadTessFactorsAvg(Spacing::kInteger, {1, 2, 3, 4}, 1.0f);
  EXPECT_EQ(f.rounded.outer, (std::array<float, 4>{1, 2, 3, 4}));
  EXPECT_EQ(f.rounded.inner, (std::array<float, 2>{3, 3}));
  EXPECT_EQ(f.unrounded_inner, (std::array<float, 2>{2.5f, 2.5f}));

  // min 4 * 0.5 = 2.
  f = processQuadTessFactorsMin(Spacing::kInteger, {4, 6, 8, 10}, 0.5f);
  EXPECT_EQ(f.rounded.inner, (std::array<float, 2>{2, 2}));

  // fractional_odd Max with scale 0 (NaN scale counts as 0): 0 clamps to 1, odd and
  // < 3, so the frame rule takes min(3, max 2.5) = 2.5.
  f = processQuadTessFactorsMax(Spacing::kFractionalOdd, {1.5f, 2.5f, 1.0f, 2.0f}, kNaN);
  EXPECT_EQ(f.rounded.inner, (std::array<float, 2>{2.5f, 2.5f}));
}

TEST(TessFactorHelpers, QuadTwoAxisReductions) {
  // Inside u from the v = 0 / v = 1 edges: (2 + 4) / 2 = 3; inside v: (1 + 3) / 2 = 2.
  ProcessedFactors f = process2DQuadTessFactorsAvg(Spacing::kInteger, {1, 2, 3, 4}, {1, 1});
  EXPECT_EQ(f.rounded.inner, (std::array<float, 2>{3, 2}));
  EXPECT_EQ(f.unrounded_inner, (std::array<float, 2>{3, 2}));

  // fractional_odd Max: u = max(2, 2) = 2, v = max(1, 1) = 1; then the odd axis below
  // 3 and below the other is raised to min(other, 3): v -> 2.
  f = process2DQuadTessFactorsMax(Spacing::kFractionalOdd, {1, 2, 1, 2}, {1, 1});
  EXPECT_EQ(f.rounded.inner, (std::array<float, 2>{2, 2}));
  EXPECT_EQ(f.unrounded_inner, (std::array<float, 2>{2, 2}));

  // fractional_odd Avg: u = (4 + 8) / 2 = 6, v = 1 -> raised to min(6, 3) = 3.
  f = process2DQuadTessFactorsAvg(Spacing::kFractionalOdd, {1, 4, 1, 8}, {1, 1});
  EXPECT_EQ(f.rounded.inner, (std::array<float, 2>{6, 3}));

  // Min with per-axis scales: u = min(10, 20) * 0.5 = 5, v = min(6, 7) * 0.25 = 1.5 -> 2.
  f = process2DQuadTessFactorsMin(Spacing::kInteger, {6, 10, 7, 20}, {0.5f, 0.25f});
  EXPECT_EQ(f.rounded.inner, (std::array<float, 2>{5, 2}));
  EXPECT_EQ(f.unrounded_inner, (std::array<float, 2>{5, 1.5f}));
}

TEST(TessFactorHelpers, IsolineAndCulling) {
  // Detail follows the partitioning (pow2: 5 -> 8); density is always integer (2.2 -> 3).
  ProcessedFactors f = processIsolineTessFactors(Spacing::kPow2, 5.0f, 2.2f);
  EXPECT_EQ(f.rounded.outer[0], 3.0f);
  EXPECT_EQ(f.rounded.outer[1], 8.0f);
  f = processIsolineTessFactors(Spacing::kFractionalOdd, 70.0f, 0.5f);
  EXPECT_EQ(f.rounded.outer[0], 1.0f);
  EXPECT_EQ(f.rounded.outer[1], 63.0f);

  // Any raw edge factor not > 0 culls: every level comes back 0.
  for (const ProcessedFactors& culled :
       {processTriTessFactorsAvg(Spacing::kInteger, {0, 5, 5}, 1),
        processQuadTessFactorsMax(Spacing::kInteger, {5, kNaN, 5, 5}, 1),
        process2DQuadTessFactorsMin(Spacing::kFractionalEven, {5, 5, 5, -1}, {1, 1}),
        processIsolineTessFactors(Spacing::kInteger, 4, 0)}) {
    EXPECT_EQ(culled.rounded.outer, (std::array<float, 4>{0, 0, 0, 0}));
    EXPECT_EQ(culled.rounded.inner, (std::array<float, 2>{0, 0}));
  }
  EXPECT_TRUE(tessellate(Domain::kTriangle, Spacing::kInteger,
                         processTriTessFactorsAvg(Spacing::kInteger, {0, 5, 5}, 1).rounded)
                  .culled);
}

TEST(TessFactorHelpers, RoundPow2LevelsKeepsCullingAndIsolineDensity) {
  Levels quad;
  quad.outer = {3.0f, 0.0f, kNaN, 65.0f};
  quad.inner = {0.2f, 33.0f};
  const Levels q = roundPow2Levels(Domain::kQuad, quad);
  EXPECT_EQ(q.outer[0], 4.0f);
  EXPECT_EQ(q.outer[1], 0.0f);  // still culls
  EXPECT_TRUE(std::isnan(q.outer[2]));
  EXPECT_EQ(q.outer[3], 64.0f);
  EXPECT_EQ(q.inner, (std::array<float, 2>{1.0f, 64.0f}));

  Levels line;
  line.outer = {2.5f, 5.0f, 7.0f, 7.0f};
  const Levels l = roundPow2Levels(Domain::kIsoline, line);
  EXPECT_EQ(l.outer, (std::array<float, 4>{2.5f, 8.0f, 7.0f, 7.0f}));

  Levels tri;
  tri.outer = {1.0f, 1.5f, 64.0f, 3.0f};
  tri.inner = {9.0f, 3.0f};
  const Levels t = roundPow2Levels(Domain::kTriangle, tri);
  EXPECT_EQ(t.outer, (std::array<float, 4>{1.0f, 2.0f, 64.0f, 3.0f}));
  EXPECT_EQ(t.inner, (std::array<float, 2>{16.0f, 3.0f}));
}

}  // namespace
}  // namespace tb::tess
