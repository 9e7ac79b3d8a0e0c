// Oracle: the in-memory map itself (a write then a read must give the same texel bits, compared
// as uint32) and Imath's half conversion (round to nearest even) for the half rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/displacement/exr_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

using testing::makeMap;
using testing::makeTilesMap;
using testing::texelBits;

void expectRoundTrip(const displacement::DisplacementMap& map, const std::string& name) {
  const std::string path = (testing::scratchDirectory("exr_round_trip") / (name + ".exr")).string();
  displacement::writeDisplacementExr(path, map);
  const displacement::DisplacementMap read = displacement::readDisplacementExr(path, map.kind);
  EXPECT_EQ(read.kind, map.kind);
  EXPECT_EQ(read.pixel_type, map.pixel_type);
  EXPECT_EQ(read.width, map.width);
  EXPECT_EQ(read.height, map.height);
  EXPECT_EQ(read.layout, map.layout);
  EXPECT_EQ(read.tiles.tile_size, map.tiles.tile_size);
  EXPECT_EQ(read.tiles.border, map.tiles.border);
  EXPECT_EQ(read.tiles.tiles_per_row, map.tiles.tiles_per_row);
  EXPECT_EQ(read.tiles.tile_count, map.tiles.tile_count);
  EXPECT_EQ(texelBits(read.texels), texelBits(map.texels));
}

TEST(ExrIo, RoundTripScalarHalfUv) {
  expectRoundTrip(makeMap(displacement::DisplacementKind::kScalar,
                          displacement::DisplacementPixelType::kHalf, 13, 7),
                  "sh");
}

TEST(ExrIo, RoundTripScalarFloatUv) {
  expectRoundTrip(makeMap(displacement::DisplacementKind::kScalar,
                          displacement::DisplacementPixelType::kFloat, 13, 7),
                  "sf");
}

TEST(ExrIo, RoundTripVectorHalfUv) {
  expectRoundTrip(makeMap(displacement::DisplacementKind::kVector,
                          displacement::DisplacementPixelType::kHalf, 5, 11),
                  "vh");
}

TEST(ExrIo, RoundTripVectorFloatUv) {
  expectRoundTrip(makeMap(displacement::DisplacementKind::kVector,
                          displacement::DisplacementPixelType::kFloat, 5, 11),
                  "vf");
}

TEST(ExrIo, RoundTripScalarHalfTiles) {
  expectRoundTrip(makeTilesMap(displacement::DisplacementKind::kScalar,
                               displacement::DisplacementPixelType::kHalf),
                  "sht");
}

TEST(ExrIo, RoundTripVectorFloatTiles) {
  expectRoundTrip(makeTilesMap(displacement::DisplacementKind::kVector,
                               displacement::DisplacementPixelType::kFloat),
                  "vft");
}

TEST(ExrIo, RoundTripKeepsSignedZeroSubnormalsAndExtremes) {
  for (const displacement::DisplacementPixelType type :
       {displacement::DisplacementPixelType::kHalf, displacement::DisplacementPixelType::kFloat}) {
    displacement::DisplacementMap map =
        makeMap(displacement::DisplacementKind::kScalar, type, 6, 1);
    const bool half = type == displacement::DisplacementPixelType::kHalf;
    map.texels = {-0.0f,
                  0.0f,
                  half ? 5.9604645e-8f : std::numeric_limits<float>::denorm_min(),
                  half ? 65504.0f : std::numeric_limits<float>::max(),
                  half ? -65504.0f : std::numeric_limits<float>::lowest(),
                  1.0f};
    expectRoundTrip(map, half ? "extremes_half" : "extremes_float");
  }
}

TEST(ExrIo, OneTexelMapRoundTrips) {
  expectRoundTrip(makeMap(displacement::DisplacementKind::kVector,
                          displacement::DisplacementPixelType::kHalf, 1, 1),
                  "one");
}

TEST(ExrIo, ReadWithoutExpectedKindAcceptsEither) {
  const auto dir = testing::scratchDirectory("exr_any_kind");
  for (const displacement::DisplacementKind kind :
       {displacement::DisplacementKind::kScalar, displacement::DisplacementKind::kVector}) {
    const std::string path = (dir / (std::string(displacement::kindName(kind)) + ".exr")).string();
    displacement::writeDisplacementExr(
        path, makeMap(kind, displacement::DisplacementPixelType::kFloat, 3, 2));
    EXPECT_EQ(displacement::readDisplacementExr(path).kind, kind);
  }
}

// Half quantisation: the writer refuses a float that is not an exact half (the round trip
// must stay bit-for-bit); roundTexelsToHalf makes the map writable, and the read-back equals
// Imath's nearest half.
TEST(ExrIo, HalfMapRefusesInexactTexelUntilRounded) {
  const auto dir = testing::scratchDirectory("exr_half_rounding");
  const std::string path = (dir / "inexact.exr").string();
  displacement::DisplacementMap map = makeMap(displacement::DisplacementKind::kScalar,
                                              displacement::DisplacementPixelType::kHalf, 2, 2);
  map.texels[3] = 0.1f;  // 0.1 is not a half; its nearest half is 0.0999755859375
  const std::string message = testing::writeError(path, map);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("texel (1, 1) channel 0"), std::string::npos) << message;
  EXPECT_NE(message.find("not representable as half"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(path));

  displacement::roundTexelsToHalf(map);
  EXPECT_EQ(map.texels[3], 0.0999755859375f);
  displacement::writeDisplacementExr(path, map);
  EXPECT_EQ(displacement::readDisplacementExr(path).texels[3], 0.0999755859375f);
}

TEST(ExrIo, RoundToHalfMatchesHalfRounding) {
  EXPECT_EQ(displacement::roundToHalf(1.0f), 1.0f);
  EXPECT_EQ(displacement::roundToHalf(1.0f + 1.0f / 2048.0f), 1.0f);  // a tie: rounds to even
  EXPECT_EQ(displacement::roundToHalf(1.0f + 3.0f / 2048.0f),
            1.0f + 2.0f / 1024.0f);                              // a tie, to even
  EXPECT_TRUE(std::isinf(displacement::roundToHalf(70000.0f)));  // past the half range
}

// A float that overflows half is refused as not representable, not written as infinity.
TEST(ExrIo, HalfMapRefusesTexelBeyondHalfRange) {
  const std::string path = (testing::scratchDirectory("exr_half_range") / "overflow.exr").string();
  displacement::DisplacementMap map = makeMap(displacement::DisplacementKind::kScalar,
                                              displacement::DisplacementPixelType::kHalf, 2, 1);
  map.texels[0] = 70000.0f;
  EXPECT_NE(testing::writeError(path, map).find("not representable as half"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace tb
