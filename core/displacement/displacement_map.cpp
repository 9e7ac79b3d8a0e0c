#include "core/displacement/displacement_map.h"

#include <Imath/half.h>

#include <cassert>
#include <cstring>

namespace tb::displacement {

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

namespace {
std::uint32_t gpuChannels(const DisplacementMap& map) {
  return map.kind == DisplacementKind::kScalar ? 1u : 4u;
}
std::uint32_t gpuChannelBytes(const DisplacementMap& map) {
  return map.pixel_type == DisplacementPixelType::kHalf ? 2u : 4u;
}
}  // namespace

std::uint64_t gpuResidentBytes(const DisplacementMap& map) {
  return std::uint64_t{map.width} * map.height * gpuChannels(map) * gpuChannelBytes(map);
}

std::vector<std::byte> gpuTexelBytes(const DisplacementMap& map) {
  const std::uint32_t channels = channelCount(map.kind), gpu_channels = gpuChannels(map);
  const std::uint32_t bytes = gpuChannelBytes(map);
  std::vector<std::byte> out(gpuResidentBytes(map), std::byte{0});
  const std::size_t texel_count = std::size_t{map.width} * map.height;
  for (std::size_t t = 0; t < texel_count; ++t) {
    for (std::uint32_t c = 0; c < channels; ++c) {
      const float value = map.texels[t * channels + c];
      std::byte* to = &out[(t * gpu_channels + c) * bytes];
      if (bytes == 2) {
        const std::uint16_t bits = Imath::half(value).bits();
        std::memcpy(to, &bits, 2);
      } else {
        std::memcpy(to, &value, 4);
      }
    }
  }
  return out;
}

float roundToHalf(float value) { return static_cast<float>(Imath::half(value)); }

void roundTexelsToHalf(DisplacementMap& map) {
  for (float& texel : map.texels) texel = roundToHalf(texel);
}

}  // namespace tb::displacement
