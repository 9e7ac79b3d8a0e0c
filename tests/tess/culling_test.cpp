// Culling, the all-ones special case and the inside-level fix-ups (oracle: the D3D11
// reference tessellator's documented rules, as lavapipe applies them).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "core/tess/tessellator.h"
#include "tests/tess/tess_test_support.h"

namespace tb::tess {
namespace {

using testing::kSpacings;
using testing::uniformLevels;

size_t outerUsed(Domain domain) {
  return domain == Domain::kTriangle ? 3 : (domain == Domain::kQuad ? 4 : 2);
}

TEST(TessCulling, AnyUsedOuterLevelZeroNegativeOrNaNCulls) {
  const float kBad[] = {0.0f,
                        -0.0f,
                        -1.0f,
                        -70.0f,
                        std::numeric_limits<float>::quiet_NaN(),
                        -std::numeric_limits<float>::infinity()};
  for (Domain domain : testing::kDomains) {
    for (Spacing spacing : kSpacings) {
      for (size_t e = 0; e < outerUsed(domain); ++e) {
        for (float bad : kBad) {
          Levels levels = uniformLevels(5.0f);
          levels.outer[e] = bad;
          const Tessellation t = tessellate(domain, spacing, levels);
          EXPECT_TRUE(t.culled) << toString(domain) << " outer[" << e << "] = " << bad;
          EXPECT_TRUE(t.points.empty());
          EXPECT_TRUE(t.triangles.empty());
          EXPECT_TRUE(t.lines.empty());
        }
      }
    }
  }
}

TEST(TessCulling, UnusedOuterAndBadInsideLevelsDoNotCull) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (Spacing spacing : kSpacings) {
    Levels tri = uniformLevels(4.0f);
    tri.outer[3] = 0.0f;
    tri.inner = {nan, -3.0f};  // a bad inside level clamps to the minimum instead
    EXPECT_FALSE(tessellate(Domain::kTriangle, spacing, tri).culled);

    Levels quad = uniformLevels(4.0f);
    quad.inner = {0.0f, nan};
    EXPECT_FALSE(tessellate(Domain::kQuad, spacing, quad).culled);

    Levels line = uniformLevels(4.0f);
    line.outer[2] = nan;
    line.outer[3] = -1.0f;
    line.inner = {nan, nan};
    EXPECT_FALSE(tessellate(Domain::kIsoline, spacing, line).culled);
  }
  // A positive level below the minimum is clamped up, not culled.
  EXPECT_FALSE(tessellate(Domain::kQuad, Spacing::kInteger, uniformLevels(1e-30f)).culled);
}

TEST(TessMinimal, AllOnesIsOneTriangleOrTwo) {
  for (Spacing spacing : {Spacing::kInteger, Spacing::kPow2, Spacing::kFractionalOdd}) {
    const Tessellation tri = tessellate(Domain::kTriangle, spacing, uniformLevels(1.0f));
    ASSERT_EQ(tri.points.size(), 3u);
    ASSERT_EQ(tri.triangles.size(), 1u);
    EXPECT_EQ(tri.points[0], (DomainPoint{0, 1, 0}));
    EXPECT_EQ(tri.points[1], (DomainPoint{0, 0, 1}));
    EXPECT_EQ(tri.points[2], (DomainPoint{1, 0, 0}));

    const Tessellation quad = tessellate(Domain::kQuad, spacing, uniformLevels(1.0f));
    ASSERT_EQ(quad.points.size(), 4u);
    ASSERT_EQ(quad.triangles.size(), 2u);
    EXPECT_EQ(quad.points[2], (DomainPoint{1, 1, 0}));
  }
  // fractional_even has no level 1: it clamps to 2 (7 points, 6 triangles).
  const Tessellation even =
      tessellate(Domain::kTriangle, Spacing::kFractionalEven, uniformLevels(1.0f));
  EXPECT_EQ(even.points.size(), 7u);
  EXPECT_EQ(even.triangles.size(), 6u);
  // Levels that convert to exactly 1.0 in 16.16 are still the minimal case; 1 + 2^-18
  // rounds down, 1 + 2^-17 is a tie that rounds to even.
  for (float almost_one : {1.0f + 0x1p-18f, 1.0f + 0x1p-17f}) {
    EXPECT_EQ(tessellate(Domain::kQuad, Spacing::kFractionalOdd, uniformLevels(almost_one))
                  .triangles.size(),
              2u);
  }
  EXPECT_GT(tessellate(Domain::kQuad, Spacing::kFractionalOdd, uniformLevels(1.0f + 0x1p-16f))
                .triangles.size(),
            2u);
}

// Integer: an inside level of 1 with a larger outer level is laid out as inside 2 (it
// gets a middle point or row rather than no interior at all).
TEST(TessFixups, IntegerInsideOneActsAsTheNextLevelUp) {
  for (Domain domain : {Domain::kTriangle, Domain::kQuad}) {
    Levels one = uniformLevels(3.0f);
    one.inner = {1.0f, 1.0f};
    Levels two = one;
    two.inner = {2.0f, 2.0f};
    const Tessellation a = tessellate(domain, Spacing::kInteger, one);
    const Tessellation b = tessellate(domain, Spacing::kInteger, two);
    EXPECT_EQ(a.points, b.points) << toString(domain);
    EXPECT_EQ(a.triangles, b.triangles) << toString(domain);
  }
}

// fractional_odd: once an outer level exceeds 1, the inside level is held above 1 so a
// ring always separates the edges. With the inside at its minimum that ring sits on
// the boundary, so lavapipe (and this model) emit points with equal coordinates: TES
// invocations are unique, coordinates need not be.
TEST(TessFixups, FractionalOddInsideIsHeldAboveOne) {
  Levels levels = uniformLevels(3.0f);
  levels.inner = {1.0f, 1.0f};
  const Tessellation tri = tessellate(Domain::kTriangle, Spacing::kFractionalOdd, levels);
  EXPECT_EQ(tri.points.size(), 12u);  // boundary 9 + an inner ring of 3
  EXPECT_EQ(tri.triangles.size(), 13u);
  const std::set<DomainPoint> distinct(tri.points.begin(), tri.points.end());
  EXPECT_EQ(distinct.size(), 9u);

  // The same inside level with every outer level 1 stays the minimal case.
  EXPECT_EQ(
      tessellate(Domain::kTriangle, Spacing::kFractionalOdd, uniformLevels(1.0f)).points.size(),
      3u);
  // For quads the raw inside levels count too: inside 1.5 alone forces the frame.
  Levels quad = uniformLevels(1.0f);
  quad.inner = {1.5f, 1.0f};
  EXPECT_GT(tessellate(Domain::kQuad, Spacing::kFractionalOdd, quad).points.size(), 4u);
}

}  // namespace
}  // namespace tb::tess
