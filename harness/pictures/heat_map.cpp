#include "harness/pictures/heat_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "harness/pictures/bitmap_font.h"

namespace tb::pictures {
namespace {

// Five points of the viridis ramp (van der Walt & Smith, matplotlib 2015) at t = 0, 1/4,
// 1/2, 3/4, 1; between them the colour is interpolated linearly. Lightness rises
// monotonically along the ramp.
constexpr std::array<Rgb, 5> kControlPoints = {Rgb{68, 1, 84}, Rgb{59, 82, 139}, Rgb{33, 145, 140},
                                               Rgb{94, 201, 98}, Rgb{253, 231, 37}};

constexpr Rgb kFrame{40, 40, 40};

uint8_t mix(uint8_t a, uint8_t b, double w) {
  return uint8_t(std::lround(double(a) + (double(b) - double(a)) * w));
}

}  // namespace

Rgb heatColour(double t) {
  if (!(t > 0)) return kControlPoints.front();  // also NaN
  if (t >= 1) return kControlPoints.back();
  const double scaled = t * double(kControlPoints.size() - 1);
  const size_t segment = std::min(size_t(scaled), kControlPoints.size() - 2);
  const double w = scaled - double(segment);
  const Rgb& a = kControlPoints[segment];
  const Rgb& b = kControlPoints[segment + 1];
  return {mix(a.r, b.r, w), mix(a.g, b.g, w), mix(a.b, b.b, w)};
}

Rgb heatColourLow() { return kControlPoints.front(); }
Rgb heatColourHigh() { return kControlPoints.back(); }

std::string scaleLabel(double value) {
  if (value == 0) return "0";
  char text[32];
  std::snprintf(text, sizeof(text), "%.1e", value);
  return text;
}

void drawColourBar(RgbImage* image, uint32_t x, uint32_t y, uint32_t width_px, uint32_t height_px,
                   double scale_max) {
  for (uint32_t i = 0; i < width_px; ++i) {
    const double t = width_px > 1 ? double(i) / double(width_px - 1) : 0;
    const Rgb colour = heatColour(t);
    for (uint32_t j = 0; j < height_px; ++j) image->set(x + i, y + j, colour);
  }
  for (uint32_t i = 0; i < width_px; ++i) {
    image->set(x + i, y, kFrame);
    image->set(x + i, y + height_px - 1, kFrame);
  }
  for (uint32_t j = 0; j < height_px; ++j) {
    image->set(x, y + j, kFrame);
    image->set(x + width_px - 1, y + j, kFrame);
  }
  constexpr int kScale = 2;
  const int64_t label_y = int64_t(y) + height_px + 3;
  drawText(image, x, label_y, "0", kScale, kFrame);
  const std::string high = scaleLabel(scale_max);
  drawText(image, int64_t(x) + width_px - textWidthPx(high, kScale), label_y, high, kScale, kFrame);
}

}  // namespace tb::pictures
