// PNG encoding with libpng (Debian's libpng-dev). The output is deterministic: 8-bit RGB,
// no interlacing, a fixed zlib level and libpng's default filter choice, and no time, text
// or gamma chunks, so equal pictures give equal bytes.
#pragma once

#include <string>

#include "harness/pictures/rgb_image.h"

namespace tb::pictures {

// zlib level of every PNG written (0 none .. 9 smallest); 9 costs ~10 ms on a 320 x 356
// picture and makes the files ~15 % smaller than the default 6.
inline constexpr int kPngCompressionLevel = 9;

// The PNG file of `image` (width and height > 0). Throws std::runtime_error with libpng's
// message when encoding fails, std::invalid_argument for an empty or inconsistent image.
std::string encodePng(const RgbImage& image);

}  // namespace tb::pictures
