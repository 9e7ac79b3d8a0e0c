#include "core/displacement/displacement_map.h"

#include <Imath/half.h>

#include <cassert>

namespace tb {

float DisplacementMap::at(std::uint32_t x, std::uint32_t y, std::uint32_t c) const {
  const std::uint32_t channels = channelCount(kind);
  assert(x < width && y < height && c < channels);
  return texels[(std::size_t{y} * width + x) * channels + c];
}

std::uint32_t channelCount(DisplacementKind kind) {
  return kind == DisplacementKind::kScalar ? 1u : 3u;
}

std::string_view kindName(DisplacementKind kind) {
  return kind == DisplacementKind::kScalar ? "scalar" : "vector";
}

std::string_view pixelTypeName(DisplacementPixelType type) {
  return type == DisplacementPixelType::kHalf ? "half" : "float";
}

std::string_view layoutName(DisplacementLayout layout) {
  return layout == DisplacementLayout::kTiles ? "tiles" : "uv";
}

float roundToHalf(float value) { return static_cast<float>(Imath::half(value)); }

void roundTexelsToHalf(DisplacementMap& map) {
  for (float& texel : map.texels) texel = roundToHalf(texel);
}

}  // namespace tb
