// Oracle: libpng's own reader (the simplified png_image API) decodes what encodePng wrote
// to the same size and pixels; the bytes do not depend on when they were written.
#include "harness/pictures/png_writer.h"

#include <gtest/gtest.h>
#include <png.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace tb {
namespace {

// Decodes PNG bytes to 8-bit RGB with libpng, or fails the test.
pictures::RgbImage decodePng(const std::string& bytes) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
    ADD_FAILURE() << "libpng cannot read the header: " << image.message;
    return {};
  }
  image.format = PNG_FORMAT_RGB;
  pictures::RgbImage decoded(image.width, image.height);
  if (!png_image_finish_read(&image, nullptr, decoded.rgb.data(), 0, nullptr)) {
    ADD_FAILURE() << "libpng cannot read the pixels: " << image.message;
  }
  return decoded;
}

// A picture with every kind of content: gradients, noise (a fixed LCG) and flat areas.
pictures::RgbImage testImage(uint32_t width, uint32_t height) {
  pictures::RgbImage image(width, height);
  uint32_t state = 12345;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      state = state * 1664525u + 1013904223u;
      if (y < height / 3) {
        image.set(x, y, {uint8_t(x), uint8_t(y), uint8_t(x + y)});
      } else if (y < 2 * height / 3) {
        image.set(x, y, {uint8_t(state >> 24), uint8_t(state >> 16), uint8_t(state >> 8)});
      }
    }
  }
  return image;
}

TEST(PngWriter, RoundTripsThroughLibpngsReader) {
  for (const auto& [width, height] :
       {std::pair{37u, 23u}, std::pair{1u, 1u}, std::pair{320u, 354u}}) {
    const pictures::RgbImage original = testImage(width, height);
    const std::string bytes = pictures::encodePng(original);
    ASSERT_GT(bytes.size(), 8u);
    EXPECT_EQ(bytes.substr(1, 3), "PNG");
    const pictures::RgbImage decoded = decodePng(bytes);
    EXPECT_EQ(decoded.width_px, width);
    EXPECT_EQ(decoded.height_px, height);
    EXPECT_EQ(decoded.rgb, original.rgb);
  }
}

TEST(PngWriter, IsDeterministicAndCarriesNoTime) {
  const pictures::RgbImage image = testImage(64, 48);
  const std::string first = pictures::encodePng(image);
  EXPECT_EQ(pictures::encodePng(image), first);
  EXPECT_EQ(first.find("tIME"), std::string::npos);
  EXPECT_EQ(first.find("tEXt"), std::string::npos);
  // A one-pixel change changes the file.
  pictures::RgbImage changed = image;
  changed.set(10, 40, {1, 2, 3});
  EXPECT_NE(pictures::encodePng(changed), first);
}

TEST(PngWriter, RefusesAnImageWhosePixelsDoNotFitItsSize) {
  pictures::RgbImage broken(4, 4);
  broken.rgb.pop_back();
  EXPECT_THROW(pictures::encodePng(broken), std::invalid_argument);
  EXPECT_THROW(pictures::encodePng(pictures::RgbImage{}), std::invalid_argument);
}

}  // namespace
}  // namespace tb
