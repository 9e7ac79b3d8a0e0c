// The colour scale of the error pictures: a perceptual ramp (dark purple, blue, teal,
// green, yellow: viridis-like, monotonic in lightness so it also reads in grey) and the
// colour bar that shows it in the picture.
#pragma once

#include <cstdint>
#include <string>

#include "harness/pictures/rgb_image.h"

namespace tb::pictures {

// Colour of t in [0, 1] (t <= 0 the first colour, t >= 1 the last; NaN the first):
// linear interpolation in 8-bit sRGB between heat_map.cpp's five control points, rounded
// to the nearest integer.
Rgb heatColour(double t);

// The ramp's ends, for the index and tests.
Rgb heatColourLow();
Rgb heatColourHigh();

// "0", or `value` with two significant digits in exponent form ("3.1e-03"): the labels of
// the colour bar.
std::string scaleLabel(double value);

// Draws the bar into the box (x, y, width_px, height_px) of `image`: the ramp left (0) to
// right (scale_max), a dark frame, and below it the labels "0" at the left end and
// scaleLabel(scale_max) at the right, in the 3 x 5 font at 2 pixels per font pixel.
// The box plus kColourBarLabelPx below it must lie inside the image.
void drawColourBar(RgbImage* image, uint32_t x, uint32_t y, uint32_t width_px, uint32_t height_px,
                   double scale_max);

// Pixels the labels take below the bar (a 3-pixel gap, then 5 font pixels at scale 2).
inline constexpr uint32_t kColourBarLabelPx = 13;

}  // namespace tb::pictures
