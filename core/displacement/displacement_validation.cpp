#include "core/displacement/displacement_validation.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "core/displacement/exr_io.h"
#include "core/mesh/input_error.h"

namespace tb::displacement {
namespace {

// Enough digits to tell two floats apart.
std::string exactText(float value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
  return text;
}

std::string texelName(const DisplacementMap& map, std::size_t index) {
  const std::uint32_t channels = channelCount(map.kind);
  const std::size_t texel = index / channels;
  return "texel (" + std::to_string(texel % map.width) + ", " + std::to_string(texel / map.width) +
         ") channel " + std::to_string(index % channels);
}

void validateResolution(const DisplacementMap& map, const std::string& file) {
  const std::string size = std::to_string(map.width) + " x " + std::to_string(map.height);
  if (map.width == 0 || map.height == 0) {
    throw mesh::InputError(file, "resolution " + size, "width and height must be at least 1");
  }
  if (map.width > kMaxDisplacementSide || map.height > kMaxDisplacementSide) {
    throw mesh::InputError(
        file, "resolution " + size,
        "width and height must be at most " + std::to_string(kMaxDisplacementSide));
  }
  const std::size_t expected = std::size_t{map.width} * map.height * channelCount(map.kind);
  if (map.texels.size() != expected) {
    throw mesh::InputError(file, "texels",
                           std::to_string(map.texels.size()) + " values, expected " +
                               std::to_string(expected) + " (" + size + " x " +
                               std::to_string(channelCount(map.kind)) + " channels)");
  }
}

void validateTiles(const DisplacementMap& map, const std::string& file) {
  if (map.layout != DisplacementLayout::kTiles) return;
  const DisplacementTiles& t = map.tiles;
  const std::string element = "tile layout (tile_size " + std::to_string(t.tile_size) +
                              ", border " + std::to_string(t.border) + ", tiles_per_row " +
                              std::to_string(t.tiles_per_row) + ", tile_count " +
                              std::to_string(t.tile_count) + ")";
  if (t.tile_size == 0 || t.tiles_per_row == 0 || t.tile_count == 0) {
    throw mesh::InputError(file, element,
                           "tile_size, tiles_per_row and tile_count must be at least 1");
  }
  if (2ull * t.border >= t.tile_size) {
    throw mesh::InputError(file, element,
                           "the borders leave no interior (2 * border >= tile_size)");
  }
  const std::uint64_t rows = (std::uint64_t{t.tile_count} + t.tiles_per_row - 1) / t.tiles_per_row;
  if (std::uint64_t{t.tile_size} * t.tiles_per_row > map.width || rows * t.tile_size > map.height) {
    throw mesh::InputError(file, element,
                           "the tiles do not fit the " + std::to_string(map.width) + " x " +
                               std::to_string(map.height) + " atlas");
  }
}

void validateTexels(const DisplacementMap& map, const std::string& file) {
  for (std::size_t i = 0; i < map.texels.size(); ++i) {
    const float value = map.texels[i];
    if (!std::isfinite(value)) {
      throw mesh::InputError(file, texelName(map, i), "not finite (NaN or infinite)");
    }
    if (map.pixel_type == DisplacementPixelType::kHalf &&
        std::bit_cast<std::uint32_t>(roundToHalf(value)) != std::bit_cast<std::uint32_t>(value)) {
      throw mesh::InputError(file, texelName(map, i),
                             "texel " + exactText(value) +
                                 " not representable as half (round it with roundTexelsToHalf)");
    }
  }
}

}  // namespace

void validateDisplacementMap(const DisplacementMap& map, const std::string& file) {
  validateResolution(map, file);
  validateTiles(map, file);
  validateTexels(map, file);
}

}  // namespace tb::displacement
