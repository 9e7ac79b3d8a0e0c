// Oracle: the ramp's own control points (viridis at 0 and 1) and lightness (Rec. 709 luma),
// which a perceptual ramp must raise monotonically; the 3 x 5 font's glyph bits.
#include "harness/pictures/heat_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "harness/pictures/bitmap_font.h"

namespace tb {
namespace {

double luma(pictures::Rgb c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

TEST(HeatMap, EndpointsAreTheRampsEnds) {
  EXPECT_EQ(pictures::heatColour(0), pictures::heatColourLow());
  EXPECT_EQ(pictures::heatColour(1), pictures::heatColourHigh());
  EXPECT_EQ(pictures::heatColourLow(), (pictures::Rgb{68, 1, 84}));
  EXPECT_EQ(pictures::heatColourHigh(), (pictures::Rgb{253, 231, 37}));
  EXPECT_EQ(pictures::heatColour(-3), pictures::heatColourLow());
  EXPECT_EQ(pictures::heatColour(7), pictures::heatColourHigh());
  EXPECT_EQ(pictures::heatColour(std::numeric_limits<double>::quiet_NaN()),
            pictures::heatColourLow());
  EXPECT_NE(pictures::heatColour(0.5), pictures::heatColourLow());
  EXPECT_NE(pictures::heatColour(0.5), pictures::heatColourHigh());
}

TEST(HeatMap, LightnessRisesMonotonically) {
  // Strictly between the control points (t = 0, 1/4, ..., 1); within a segment, up to the
  // rounding of each channel to an integer (one red step is 0.21 of luma).
  for (int k = 0; k < 4; ++k)
    EXPECT_LT(luma(pictures::heatColour(k / 4.0)), luma(pictures::heatColour((k + 1) / 4.0)));
  double previous = luma(pictures::heatColour(0));
  for (int i = 1; i <= 1000; ++i) {
    const double current = luma(pictures::heatColour(i / 1000.0));
    EXPECT_GE(current, previous - 0.25) << "t = " << i / 1000.0;
    previous = current;
  }
  EXPECT_GT(luma(pictures::heatColourHigh()) - luma(pictures::heatColourLow()), 150);
}

TEST(HeatMap, ColourBarRunsFromLowToHighWithItsLabels) {
  pictures::RgbImage image(200, 40);
  pictures::drawColourBar(&image, 10, 5, 180, 12, 3.14e-3);
  // Inside the frame: the first column is the low colour, the last the high one.
  EXPECT_EQ(image.at(11, 10), pictures::heatColour(1.0 / 179));
  EXPECT_EQ(image.at(188, 10), pictures::heatColour(178.0 / 179));
  EXPECT_LT(luma(image.at(11, 10)), luma(image.at(100, 10)));
  EXPECT_LT(luma(image.at(100, 10)), luma(image.at(188, 10)));
  // Labels below the bar: something dark drawn under both ends, nothing in the middle.
  auto darkIn = [&](uint32_t x0, uint32_t x1) {
    int dark = 0;
    for (uint32_t y = 17; y < 40; ++y) {
      for (uint32_t x = x0; x < x1; ++x) dark += image.at(x, y) != pictures::kWhite;
    }
    return dark;
  };
  EXPECT_GT(darkIn(10, 20), 0);
  EXPECT_GT(darkIn(150, 190), 0);
  EXPECT_EQ(darkIn(60, 120), 0);
  EXPECT_EQ(pictures::scaleLabel(3.14e-3), "3.1e-03");
  EXPECT_EQ(pictures::scaleLabel(0), "0");
}

TEST(BitmapFont, DrawsGlyphBitsAndRefusesUnknownCharacters) {
  pictures::RgbImage image(20, 10);
  pictures::drawText(&image, 1, 1, "8", 1, {0, 0, 0});
  int set = 0;
  for (uint32_t y = 0; y < 10; ++y) {
    for (uint32_t x = 0; x < 20; ++x) set += image.at(x, y) != pictures::kWhite;
  }
  EXPECT_EQ(set, 13);  // 3 + 2 + 3 + 2 + 3 font pixels
  EXPECT_EQ(pictures::textWidthPx("1.0e-03", 2), (6 * 4 + 3) * 2);
  EXPECT_THROW(pictures::drawText(&image, 0, 0, "x", 1, {0, 0, 0}), std::invalid_argument);
  // Drawing past the border is clipped, not a crash.
  pictures::drawText(&image, 18, 8, "0", 3, {0, 0, 0});
}

}  // namespace
}  // namespace tb
