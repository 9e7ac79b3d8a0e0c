#include "harness/pictures/bitmap_font.h"

#include <array>
#include <stdexcept>
#include <string>

namespace tb::pictures {
namespace {

// Each glyph is 5 rows of 3 bits, the most significant bit the left column.
struct Glyph {
  char character;
  std::array<uint8_t, kGlyphHeight> rows;
};

constexpr Glyph kGlyphs[] = {
    {'0', {0b111, 0b101, 0b101, 0b101, 0b111}}, {'1', {0b010, 0b110, 0b010, 0b010, 0b111}},
    {'2', {0b111, 0b001, 0b111, 0b100, 0b111}}, {'3', {0b111, 0b001, 0b011, 0b001, 0b111}},
    {'4', {0b101, 0b101, 0b111, 0b001, 0b001}}, {'5', {0b111, 0b100, 0b111, 0b001, 0b111}},
    {'6', {0b111, 0b100, 0b111, 0b101, 0b111}}, {'7', {0b111, 0b001, 0b010, 0b010, 0b010}},
    {'8', {0b111, 0b101, 0b111, 0b101, 0b111}}, {'9', {0b111, 0b101, 0b111, 0b001, 0b111}},
    {'.', {0b000, 0b000, 0b000, 0b000, 0b010}}, {'-', {0b000, 0b000, 0b111, 0b000, 0b000}},
    {'+', {0b000, 0b010, 0b111, 0b010, 0b000}}, {'e', {0b000, 0b111, 0b111, 0b100, 0b111}},
    {' ', {0b000, 0b000, 0b000, 0b000, 0b000}},
};

const Glyph& glyphOf(char c) {
  for (const Glyph& glyph : kGlyphs) {
    if (glyph.character == c) return glyph;
  }
  throw std::invalid_argument(std::string("drawText: the font has no '") + c + "'");
}

}  // namespace

int64_t textWidthPx(std::string_view text, int scale) {
  if (text.empty()) return 0;
  return (int64_t(text.size() - 1) * kGlyphAdvance + kGlyphWidth) * scale;
}

void drawText(RgbImage* image, int64_t x, int64_t y, std::string_view text, int scale, Rgb colour) {
  for (size_t i = 0; i < text.size(); ++i) {
    const Glyph& glyph = glyphOf(text[i]);
    const int64_t left = x + int64_t(i) * kGlyphAdvance * scale;
    for (int row = 0; row < kGlyphHeight; ++row) {
      for (int column = 0; column < kGlyphWidth; ++column) {
        if (((glyph.rows[row] >> (kGlyphWidth - 1 - column)) & 1) == 0) continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx) {
            image->setClipped(left + column * scale + dx, y + row * scale + dy, colour);
          }
        }
      }
    }
  }
}

}  // namespace tb::pictures
