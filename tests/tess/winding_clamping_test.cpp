// Winding (oracle: signed area in the (u, v) plane with v up, GL's layout(ccw)) and
// level clamping (oracle: the D3D11.3 spec §11 ranges: integer/pow2 [1, 64] rounded up,
// fractional_odd [1, 63], fractional_even [2, 64]).
#include <gtest/gtest.h>

#include <random>

#include "core/tess/tessellator.h"
#include "tests/tess/tess_test_support.h"

namespace tb::tess {
namespace {

using testing::uniformLevels;

// Every level at `level`, except the isoline density, which is always integer and so
// is held at 3 to compare the detail alone.
Levels levelsFor(Domain domain, float level) {
  Levels levels = uniformLevels(level);
  if (domain == Domain::kIsoline) levels.outer[0] = 3.0f;
  return levels;
}

void expectSameTessellation(Domain domain, Spacing spacing, const Levels& a, const Levels& b) {
  const Tessellation ta = tessellate(domain, spacing, a);
  const Tessellation tb = tessellate(domain, spacing, b);
  EXPECT_EQ(ta.points, tb.points) << toString(domain) << " " << toString(spacing);
  EXPECT_EQ(ta.triangles, tb.triangles) << toString(domain) << " " << toString(spacing);
  EXPECT_EQ(ta.lines, tb.lines) << toString(domain) << " " << toString(spacing);
}

TEST(TessWinding, CwIsCcwWithTwoVerticesSwapped) {
  std::mt19937 rng(17);
  for (Domain domain : {Domain::kTriangle, Domain::kQuad}) {
    for (Spacing spacing : testing::kSpacings) {
      const Levels levels = testing::randomLevels(rng, 1.0f, 64.0f);
      const Tessellation ccw =
          tessellate(domain, spacing, levels, {.point_mode = false, .ccw = true});
      const Tessellation cw =
          tessellate(domain, spacing, levels, {.point_mode = false, .ccw = false});
      ASSERT_EQ(ccw.points, cw.points);
      ASSERT_EQ(ccw.triangles.size(), cw.triangles.size());
      for (size_t i = 0; i < ccw.triangles.size(); ++i) {
        const auto& a = ccw.triangles[i];
        EXPECT_EQ(cw.triangles[i], (std::array<uint32_t, 3>{a[0], a[2], a[1]}));
      }
    }
  }
}

TEST(TessWinding, AreasArePositiveInTheChosenWinding) {
  for (Domain domain : {Domain::kTriangle, Domain::kQuad}) {
    for (uint32_t n = 1; n <= 64; ++n) {
      const Levels levels = uniformLevels(float(n));
      for (bool ccw : {true, false}) {
        const Tessellation t = tessellate(domain, Spacing::kInteger, levels, {.ccw = ccw});
        for (double a : testing::doubleAreas(t)) {
          ASSERT_GT(ccw ? a : -a, 0.0) << toString(domain) << " n = " << n;
        }
      }
    }
  }
}

TEST(TessWinding, PointModeEmitsPointsOnly) {
  for (Domain domain : testing::kDomains) {
    const Tessellation full = tessellate(domain, Spacing::kFractionalOdd, uniformLevels(6.5f));
    const Tessellation points =
        tessellate(domain, Spacing::kFractionalOdd, uniformLevels(6.5f), {.point_mode = true});
    EXPECT_EQ(points.points, full.points);
    EXPECT_TRUE(points.triangles.empty());
    EXPECT_TRUE(points.lines.empty());
  }
}

TEST(TessClamping, LevelsAboveTheRangeClampToTheMaximum) {
  for (Domain domain : testing::kDomains) {
    expectSameTessellation(domain, Spacing::kInteger, levelsFor(domain, 65.0f),
                           levelsFor(domain, 64.0f));
    expectSameTessellation(domain, Spacing::kInteger, levelsFor(domain, 1e30f),
                           levelsFor(domain, 64.0f));
    expectSameTessellation(domain, Spacing::kFractionalEven, levelsFor(domain, 70.0f),
                           levelsFor(domain, 64.0f));
    // fractional_odd tops out at 63: 63.9 and 64 both become 63.
    expectSameTessellation(domain, Spacing::kFractionalOdd, levelsFor(domain, 63.9f),
                           levelsFor(domain, 63.0f));
    expectSameTessellation(domain, Spacing::kFractionalOdd, levelsFor(domain, 64.0f),
                           levelsFor(domain, 63.0f));
  }
  // The isoline density is integer whatever the spacing: 64.5 lines clamp to 64.
  Levels line = uniformLevels(3.0f);
  line.outer[0] = 64.5f;
  EXPECT_EQ(tessellate(Domain::kIsoline, Spacing::kFractionalOdd, line).lines.size(), 64u * 3u);
}

TEST(TessClamping, LevelsBelowTheRangeClampToTheMinimumAndIntegerRoundsUp) {
  for (Domain domain : testing::kDomains) {
    expectSameTessellation(domain, Spacing::kFractionalEven, levelsFor(domain, 0.5f),
                           levelsFor(domain, 2.0f));
    expectSameTessellation(domain, Spacing::kFractionalOdd, levelsFor(domain, 0.25f),
                           levelsFor(domain, 1.0f));
    expectSameTessellation(domain, Spacing::kInteger, levelsFor(domain, 2.2f),
                           levelsFor(domain, 3.0f));
    expectSameTessellation(domain, Spacing::kInteger, levelsFor(domain, 1.0f + 0x1p-18f),
                           levelsFor(domain, 2.0f));
  }
  // Isoline density rounds up even with fractional detail: 2.3 -> 3 lines.
  Levels line;
  line.outer = {2.3f, 4.0f, 1, 1};
  EXPECT_EQ(tessellate(Domain::kIsoline, Spacing::kFractionalEven, line).lines.size(), 3u * 4u);
}

TEST(TessClamping, Pow2RoundsUpToAPowerOfTwoThenActsAsInteger) {
  for (Domain domain : testing::kDomains) {
    expectSameTessellation(domain, Spacing::kPow2, levelsFor(domain, 5.0f),
                           levelsFor(domain, 8.0f));
    const Tessellation pow2 = tessellate(domain, Spacing::kPow2, levelsFor(domain, 5.0f));
    const Tessellation integer = tessellate(domain, Spacing::kInteger, levelsFor(domain, 8.0f));
    EXPECT_EQ(pow2.points, integer.points) << toString(domain);
    EXPECT_EQ(pow2.triangles, integer.triangles) << toString(domain);
  }
  // Isoline density stays integer under pow2: 3 lines of 8 segments.
  Levels line;
  line.outer = {3.0f, 5.0f, 1, 1};
  EXPECT_EQ(tessellate(Domain::kIsoline, Spacing::kPow2, line).lines.size(), 3u * 8u);
}

}  // namespace
}  // namespace tb::tess
