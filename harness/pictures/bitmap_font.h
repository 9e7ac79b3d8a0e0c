// A 3 x 5 pixel font of the characters a colour-bar label needs (digits, '.', '-', '+',
// 'e', ' '), so a picture carries its scale without a font library.
#pragma once

#include <cstdint>
#include <string_view>

#include "harness/pictures/rgb_image.h"

namespace tb::pictures {

inline constexpr int kGlyphWidth = 3;    // font pixels
inline constexpr int kGlyphHeight = 5;   // font pixels
inline constexpr int kGlyphAdvance = 4;  // font pixels from one character to the next

// Width in picture pixels of `text` drawn at `scale` picture pixels per font pixel.
int64_t textWidthPx(std::string_view text, int scale);

// Draws `text` with its top-left corner at (x, y), each font pixel a scale x scale square;
// parts outside the picture are left out. Throws std::invalid_argument naming a character
// the font does not have.
void drawText(RgbImage* image, int64_t x, int64_t y, std::string_view text, int scale, Rgb colour);

}  // namespace tb::pictures
