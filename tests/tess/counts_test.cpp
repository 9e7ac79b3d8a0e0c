// Point and primitive counts of tessellate() against closed forms (oracle: the counts in
// core/tess/counts.cpp, which docs/ARCHITECTURE.md records as matching lavapipe's pipeline
// statistics: quad 2n^2 triangles and (n+1)^2 points, triangle floor(3n^2/2)).
#include <gtest/gtest.h>

#include "core/tess/tessellator.h"
#include "tests/tess/tess_test_support.h"

namespace tb::tess {
namespace {

using testing::uniformLevels;

TEST(TessCounts, QuadMatchesClosedFormForEveryIntegerLevel) {
  for (uint32_t n = 1; n <= 64; ++n) {
    const Tessellation t = tessellate(Domain::kQuad, Spacing::kInteger, uniformLevels(float(n)));
    ASSERT_FALSE(t.culled);
    EXPECT_EQ(t.points.size(), quadPointCount(n)) << "n = " << n;
    EXPECT_EQ(t.triangles.size(), quadTriangleCount(n)) << "n = " << n;
    EXPECT_EQ(t.points.size(), uint64_t(n + 1) * (n + 1));
    EXPECT_EQ(t.triangles.size(), 2ull * n * n);
    EXPECT_TRUE(t.lines.empty());
  }
}

TEST(TessCounts, TriangleMatchesClosedFormForEveryIntegerLevel) {
  for (uint32_t n = 1; n <= 64; ++n) {
    const Tessellation t =
        tessellate(Domain::kTriangle, Spacing::kInteger, uniformLevels(float(n)));
    ASSERT_FALSE(t.culled);
    EXPECT_EQ(t.points.size(), trianglePointCount(n)) << "n = " << n;
    EXPECT_EQ(t.triangles.size(), triangleTriangleCount(n)) << "n = " << n;
    EXPECT_EQ(t.triangles.size(), (3ull * n * n) / 2);
  }
  // Spot values worked by hand: level 3 has rings of 9 and 3 points; level 4 has rings
  // of 12 and 6 points plus the centre.
  EXPECT_EQ(trianglePointCount(3), 12u);
  EXPECT_EQ(trianglePointCount(4), 19u);
}

TEST(TessCounts, FractionalAtIntegerLevelsOfTheirParityMatchInteger) {
  for (uint32_t n = 3; n <= 63; n += 2) {
    const Tessellation odd =
        tessellate(Domain::kQuad, Spacing::kFractionalOdd, uniformLevels(float(n)));
    EXPECT_EQ(odd.points.size(), quadPointCount(n)) << "n = " << n;
    EXPECT_EQ(odd.triangles.size(), quadTriangleCount(n)) << "n = " << n;
  }
  for (uint32_t n = 2; n <= 64; n += 2) {
    const Tessellation even =
        tessellate(Domain::kTriangle, Spacing::kFractionalEven, uniformLevels(float(n)));
    EXPECT_EQ(even.points.size(), trianglePointCount(n)) << "n = " << n;
    EXPECT_EQ(even.triangles.size(), triangleTriangleCount(n)) << "n = " << n;
  }
}

TEST(TessCounts, IsolineHasDensityLinesOfDetailSegments) {
  for (uint32_t density = 1; density <= 64; density += 7) {
    for (uint32_t detail = 1; detail <= 64; detail += 5) {
      Levels l;
      l.outer = {float(density), float(detail), 0, 0};  // unused levels must not cull
      const Tessellation t = tessellate(Domain::kIsoline, Spacing::kInteger, l);
      ASSERT_FALSE(t.culled);
      EXPECT_EQ(t.points.size(), size_t(density) * (detail + 1));
      EXPECT_EQ(t.lines.size(), size_t(density) * detail);
      EXPECT_TRUE(t.triangles.empty());
      // Lines sit at v = i / density (never at v = 1) and span u = 0 .. 1.
      EXPECT_EQ(t.points.front()[1], 0.0f);
      EXPECT_LT(t.points.back()[1], 1.0f);
      EXPECT_EQ(t.points.back()[0], 1.0f);
    }
  }
}

}  // namespace
}  // namespace tb::tess
