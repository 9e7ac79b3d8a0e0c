// Pinned lavapipe output. Oracle: captures from lavapipe on Debian 12 (Mesa 22.3.6,
// LLVM 15.0.6), one draw per patch, TES writing gl_TessCoord bits and a geometry shader
// writing each primitive's vertices to SSBOs, domain origin LOWER_LEFT, levels fed
// bit-exactly from a buffer; pow2 fed through roundPow2Levels with equal_spacing. Each
// capture is reduced to counts and an FNV-1a digest of points (in TES invocation
// order) and primitives (in emission order); testing::outputDigest is the same
// reduction. The full random comparison (>= 2,000 level sets per domain x spacing) is
// the GPU test's job; these cases keep the model honest without a GPU.
#include <gtest/gtest.h>

#include <limits>

#include "core/tess/tessellator.h"
#include "tests/tess/tess_test_support.h"

namespace tb::tess {
namespace {

struct Capture {
  Domain domain;
  Spacing spacing;
  bool ccw;
  Levels levels;
  size_t points;
  size_t primitives;
  uint64_t digest;
};

TEST(TessLavapipeGolden, MatchesCapturedOutputBitForBit) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Capture kCaptures[] = {
      {Domain::kTriangle,
       Spacing::kInteger,
       true,
       {{1, 1, 1, 1}, {1, 1}},
       3,
       1,
       0x0eccbcd57666e864ull},
      {Domain::kTriangle,
       Spacing::kFractionalOdd,
       true,
       {{3.5f, 2.25f, 7.1f, 1}, {4.7f, 1}},
       29,
       39,
       0x89b7cf9547aaef7full},
      {Domain::kTriangle,
       Spacing::kFractionalOdd,
       false,
       {{3, 3, 3, 1}, {1, 1}},
       12,
       13,
       0x8ccfc49fb0995c31ull},
      {Domain::kTriangle,
       Spacing::kFractionalEven,
       true,
       {{5.3f, 64.0f, 2.0001f, 1}, {9.9f, 1}},
       135,
       194,
       0xa91e9777654bfb64ull},
      {Domain::kQuad,
       Spacing::kInteger,
       false,
       {{4, 3, 6, 5}, {7, 2}},
       24,
       28,
       0x87560ffe3176469full},
      {Domain::kQuad,
       Spacing::kPow2,
       true,
       {{3, 5, 9, 17}, {6, 33}},
       501,
       940,
       0x2da8f8305511d9c1ull},
      {Domain::kQuad,
       Spacing::kFractionalOdd,
       true,
       {{1.5f, 7.25f, 33.3f, 2.9f}, {4.1f, 17.6f}},
       122,
       192,
       0x3f81c0c8c5434c88ull},
      {Domain::kQuad,
       Spacing::kFractionalEven,
       true,
       {{63.9f, 2, 12.5f, 65}, {2.2f, nan}},
       147,
       148,
       0x3c859179542bf60eull},
      // 212 of these triangles are slightly inverted slivers, on lavapipe too.
      {Domain::kQuad,
       Spacing::kFractionalEven,
       true,
       {{0x1.d781fap+5f, 0x1.55c6fp+5f, 0x1.44925ep+4f, 0x1.4adaa8p+5f},
        {0x1.a2651p+5f, 0x1.e01678p+4f}},
       1811,
       3452,
       0xa8070a0c4e044dc6ull},
      {Domain::kIsoline,
       Spacing::kInteger,
       true,
       {{64, 64, 1, 1}, {1, 1}},
       4160,
       4096,
       0xd82653cdd8edb95dull},
      {Domain::kIsoline,
       Spacing::kFractionalOdd,
       true,
       {{4.5f, 9.3f, 1, 1}, {1, 1}},
       60,
       55,
       0x0a27be73e432e82full},
  };
  for (const Capture& c : kCaptures) {
    const Tessellation t = tessellate(c.domain, c.spacing, c.levels, {.ccw = c.ccw});
    const std::string what = std::string(toString(c.domain)) + " " +
                             std::string(toString(c.spacing)) + (c.ccw ? " ccw" : " cw");
    EXPECT_EQ(t.points.size(), c.points) << what;
    EXPECT_EQ(t.triangles.size() + t.lines.size(), c.primitives) << what;
    EXPECT_EQ(testing::outputDigest(t), c.digest) << what;
  }
}

}  // namespace
}  // namespace tb::tess
