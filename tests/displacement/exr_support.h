// Maps and files shared by the displacement tests.
#pragma once

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "core/displacement/displacement_map.h"
#include "core/displacement/exr_io.h"
#include "core/mesh/input_error.h"

namespace tb::testing {

// A width x height map whose texels are distinct, non-trivial values (negative, tiny,
// large), exact halves when the map is half.
inline displacement::DisplacementMap makeMap(displacement::DisplacementKind kind,
                                             displacement::DisplacementPixelType type,
                                             std::uint32_t width, std::uint32_t height) {
  displacement::DisplacementMap map;
  map.kind = kind;
  map.pixel_type = type;
  map.width = width;
  map.height = height;
  const std::size_t count = std::size_t{width} * height * displacement::channelCount(kind);
  for (std::size_t i = 0; i < count; ++i) {
    const float value =
        (static_cast<float>(i % 97) - 48.0f) * 0.0137f + 1e-5f * static_cast<float>(i);
    map.texels.push_back(type == displacement::DisplacementPixelType::kHalf
                             ? displacement::roundToHalf(value)
                             : value);
  }
  return map;
}

inline displacement::DisplacementMap makeTilesMap(displacement::DisplacementKind kind,
                                                  displacement::DisplacementPixelType type) {
  displacement::DisplacementMap map = makeMap(kind, type, 24, 16);
  map.layout = displacement::DisplacementLayout::kTiles;
  map.tiles = {.tile_size = 8, .border = 1, .tiles_per_row = 3, .tile_count = 5};
  return map;
}

inline std::vector<std::uint32_t> texelBits(const std::vector<float>& texels) {
  std::vector<std::uint32_t> bits;
  for (float texel : texels) bits.push_back(std::bit_cast<std::uint32_t>(texel));
  return bits;
}

inline std::vector<char> fileBytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

inline std::string writeBytes(const std::filesystem::path& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path.string();
}

// The message of the InputError that reading path throws, or "" when it reads.
inline std::string readError(
    const std::string& path,
    std::optional<displacement::DisplacementKind> expected = std::nullopt) {
  try {
    displacement::readDisplacementExr(path, expected);
  } catch (const mesh::InputError& error) {
    return error.what();
  }
  return "";
}

inline std::string writeError(const std::string& path, const displacement::DisplacementMap& map) {
  try {
    displacement::writeDisplacementExr(path, map);
  } catch (const mesh::InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace tb::testing
