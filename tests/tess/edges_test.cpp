// Edge placement: mirror symmetry, independence from the other levels (so neighbouring
// patches agree on a shared edge), and the 16.16 arithmetic it is built on (oracle: the
// D3D11 rules; the reciprocal spot values are entries of the reference tessellator's
// table).
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "core/tess/edge_spacing.h"
#include "core/tess/fixed_point.h"
#include "core/tess/tessellator.h"
#include "tests/tess/tess_test_support.h"

namespace tb::tess {
namespace {

using testing::edgeParameters;

constexpr int kU = 0;
constexpr int kV = 1;

TEST(TessEdges, FractionalEdgesAreMirrorSymmetricWithMiddleAtHalf) {
  for (Spacing spacing : {Spacing::kFractionalOdd, Spacing::kFractionalEven}) {
    for (float level = 1.0f; level <= 64.0f; level += 0.37f) {
      Levels levels = testing::uniformLevels(4.0f);
      levels.outer[0] = level;
      const Tessellation t = tessellate(Domain::kQuad, spacing, levels);
      const std::vector<float> params = edgeParameters(t, kU, 0.0f, kV);
      ASSERT_GE(params.size(), 2u);
      for (size_t i = 0; i < params.size(); ++i) {
        // Exact: the second half is computed as 1 - (the mirrored first-half point).
        ASSERT_EQ(params[i], 1.0f - params[params.size() - 1 - i]) << "level " << level;
      }
      const bool has_middle = params.size() % 2 == 1;
      EXPECT_EQ(has_middle, spacing == Spacing::kFractionalEven) << "level " << level;
      if (has_middle) {
        EXPECT_EQ(params[params.size() / 2], 0.5f);
      }
    }
  }
}

TEST(TessEdges, EdgePointsDependOnlyOnThatEdgesLevel) {
  std::mt19937 rng(3);
  for (Spacing spacing : testing::kSpacings) {
    for (int trial = 0; trial < 40; ++trial) {
      const float edge_level = std::uniform_real_distribution<float>(1.0f, 64.0f)(rng);
      std::vector<float> reference;
      for (int other = 0; other < 5; ++other) {
        Levels levels = testing::randomLevels(rng, 2.0f, 64.0f);
        levels.outer[1] = edge_level;  // the v = 0 edge
        const Tessellation t = tessellate(Domain::kQuad, spacing, levels);
        const std::vector<float> params = edgeParameters(t, kV, 0.0f, kU);
        if (other == 0) reference = params;
        ASSERT_EQ(params, reference) << toString(spacing) << " level " << edge_level;
      }
    }
  }
}

// Two quads sharing an edge (one's u = 1 edge is the other's u = 0 edge) and two
// triangles sharing an edge, each walked in its own direction, place identical points
// given the same level: the parameter sets agree exactly, mirrored or not.
TEST(TessEdges, PatchesSharingAnEdgeAgree) {
  std::mt19937 rng(5);
  for (Spacing spacing : testing::kSpacings) {
    for (int trial = 0; trial < 40; ++trial) {
      const float shared = std::uniform_real_distribution<float>(0.5f, 66.0f)(rng);
      Levels left = testing::randomLevels(rng, 2.0f, 64.0f);
      Levels right = testing::randomLevels(rng, 2.0f, 64.0f);
      left.outer[2] = shared;   // u = 1
      right.outer[0] = shared;  // u = 0
      EXPECT_EQ(edgeParameters(tessellate(Domain::kQuad, spacing, left), kU, 1.0f, kV),
                edgeParameters(tessellate(Domain::kQuad, spacing, right), kU, 0.0f, kV));

      Levels tri = testing::randomLevels(rng, 2.0f, 64.0f);
      tri.outer[0] = shared;  // u = 0, parameter v
      tri.outer[1] = shared;  // v = 0, parameter u
      const Tessellation t = tessellate(Domain::kTriangle, spacing, tri);
      EXPECT_EQ(edgeParameters(t, kU, 0.0f, kV), edgeParameters(t, kV, 0.0f, kU));
    }
  }
}

TEST(TessFixedPoint, ConversionRoundsHalfToEvenAndSaturates) {
  EXPECT_EQ(fxp::fromFloat(1.0f), 0x10000u);
  EXPECT_EQ(fxp::fromFloat(1.0f + 0x1p-17f), 0x10000u);      // tie, even stays
  EXPECT_EQ(fxp::fromFloat(1.0f + 3 * 0x1p-17f), 0x10002u);  // tie, odd rounds up
  EXPECT_EQ(fxp::fromFloat(1.0f + 0x1p-18f), 0x10000u);
  EXPECT_EQ(fxp::fromFloat(63.9f), 0x3fe666u);  // 63.9f = 0x1.ff3334p+5
  EXPECT_EQ(fxp::fromFloat(0x1p-17f), 0u);      // tie at zero
  EXPECT_EQ(fxp::fromFloat(-2.0f), 0u);
  EXPECT_EQ(fxp::fromFloat(std::numeric_limits<float>::quiet_NaN()), 0u);
  EXPECT_EQ(fxp::fromFloat(40000.0f), 0xffffffffu);
  EXPECT_EQ(fxp::toFloat(0x8000u), 0.5f);
  EXPECT_EQ(fxp::ceil(0x18000u), 0x20000u);
  EXPECT_EQ(fxp::floor(0x18000u), 0x10000u);
  // Reciprocals round to nearest with ties up.
  EXPECT_EQ(fxp::reciprocal(1), 0x10000u);
  EXPECT_EQ(fxp::reciprocal(3), 0x5555u);
  EXPECT_EQ(fxp::reciprocal(6), 0x2aabu);
  EXPECT_EQ(fxp::reciprocal(34), 0x788u);
  EXPECT_EQ(fxp::reciprocal(63), 0x410u);
  EXPECT_EQ(fxp::reciprocal(64), 0x400u);
  EXPECT_EQ(fxp::removeHighestBit(0), 0);
  EXPECT_EQ(fxp::removeHighestBit(13), 5);
}

// Placement worked by hand: fractional_odd level 3.5 has 5 segments (6 points) and
// half-level 2.25 (floor 2, ceil 3), blending the 3- and 5-segment layouts by 0.25.
TEST(TessFixedPoint, PlacesAFractionalOddLevelLikeTheHandComputation) {
  const EdgeSpacing s = makeEdgeSpacing(fxp::fromFloat(3.5f), Parity::kOdd);
  EXPECT_EQ(s.point_count, 6);
  EXPECT_EQ(s.half_points, 3);
  EXPECT_EQ(s.half_fraction, 0x4000u);
  EXPECT_EQ(s.split_point, 1);
  EXPECT_EQ(placePoint(s, 0), 0u);
  // Point 1: floor layout index 1 of 3 segments (0x5555), ceil index 1 of 5 (0x3333):
  // (0x5555 * 0xc000 + 0x3333 * 0x4000 + 0x8000) >> 16 = 0x4ccd.
  EXPECT_EQ(placePoint(s, 1), 0x4ccdu);
  // Point 2 lags one point behind on the floor layout (past the split point).
  EXPECT_EQ(placePoint(s, 2), (0x5555u * 0xc000u + 0x6666u * 0x4000u + 0x8000u) >> 16);
  EXPECT_EQ(placePoint(s, 5), 0x10000u);
  EXPECT_EQ(placePoint(s, 4), 0x10000u - 0x4ccdu);
}

}  // namespace
}  // namespace tb::tess
