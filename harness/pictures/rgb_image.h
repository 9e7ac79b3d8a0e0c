// An 8-bit RGB picture in memory: what the pictures compose on the CPU and png_writer.h
// encodes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tb::pictures {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

inline constexpr Rgb kWhite{255, 255, 255};

struct RgbImage {
  uint32_t width_px = 0;
  uint32_t height_px = 0;
  std::vector<uint8_t> rgb;  // row-major, top row first, 3 bytes (R, G, B) per pixel

  RgbImage() = default;
  RgbImage(uint32_t width, uint32_t height, Rgb fill = kWhite)
      : width_px(width), height_px(height), rgb(size_t(width) * height * 3) {
    for (size_t i = 0; i < rgb.size(); i += 3) {
      rgb[i] = fill.r;
      rgb[i + 1] = fill.g;
      rgb[i + 2] = fill.b;
    }
  }
  // x < width_px, y < height_px (unchecked).
  Rgb at(uint32_t x, uint32_t y) const {
    const uint8_t* p = &rgb[(size_t(y) * width_px + x) * 3];
    return {p[0], p[1], p[2]};
  }
  void set(uint32_t x, uint32_t y, Rgb colour) {
    uint8_t* p = &rgb[(size_t(y) * width_px + x) * 3];
    p[0] = colour.r;
    p[1] = colour.g;
    p[2] = colour.b;
  }
  // Pixels outside the picture are ignored (for drawing near the border).
  void setClipped(int64_t x, int64_t y, Rgb colour) {
    if (x >= 0 && y >= 0 && x < int64_t(width_px) && y < int64_t(height_px)) {
      set(uint32_t(x), uint32_t(y), colour);
    }
  }
};

}  // namespace tb::pictures
