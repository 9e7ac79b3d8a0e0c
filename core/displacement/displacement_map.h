// A displacement map in memory: scalar (1 channel, along the normal) or vector (3 channels)
// texels, stored in a file as half or float, laid out either as a per-patch tile atlas or as
// the asset's own UV atlas (docs/FORMATS.md, "Displacement maps").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace tb::displacement {

enum class DisplacementKind { kScalar, kVector };
enum class DisplacementPixelType { kHalf, kFloat };
enum class DisplacementLayout { kTiles, kUv };

// Per-patch tile atlas: patch p owns the square tile at column p % tiles_per_row, row
// p / tiles_per_row, whose top-left texel is (column * tile_size, row * tile_size).
struct DisplacementTiles {
  std::uint32_t tile_size = 0;  // texels per tile side, border included (>= 1)
  std::uint32_t border = 0;     // texels of border on each side of a tile (2*border < tile_size)
  std::uint32_t tiles_per_row = 0;  // tiles side by side in one row of the atlas (>= 1)
  std::uint32_t tile_count = 0;     // tiles in the atlas, one per patch (>= 1)
};

struct DisplacementMap {
  DisplacementKind kind = DisplacementKind::kScalar;
  // How the file stores the texels. The in-memory texels of a half map are exact halves,
  // so a write-read round trip is bit-for-bit (roundTexelsToHalf makes them so).
  DisplacementPixelType pixel_type = DisplacementPixelType::kFloat;
  std::uint32_t width = 0;   // texels per row (>= 1)
  std::uint32_t height = 0;  // rows (>= 1)
  // width * height * channelCount(kind) values in object units, row-major from the top row,
  // a texel's channels interleaved (x, y, z for a vector map).
  std::vector<float> texels;
  DisplacementLayout layout = DisplacementLayout::kUv;
  DisplacementTiles tiles;  // meaningful only when layout == kTiles

  // Texel (x, y)'s channel c; x < width, y < height, c < channelCount(kind).
  float at(std::uint32_t x, std::uint32_t y, std::uint32_t c) const;
};

std::uint32_t channelCount(DisplacementKind kind);
std::string_view kindName(DisplacementKind kind);            // "scalar", "vector"
std::string_view pixelTypeName(DisplacementPixelType type);  // "half", "float"
std::string_view layoutName(DisplacementLayout layout);      // "tiles", "uv" (as in results)

// The map as the GPU samples it (core/gpu's GpuDisplacement): one channel (R) for a scalar
// map, four (RGBA, A = 0) for a vector map, since three-channel formats are rarely
// sampleable; 16-bit float channels for a half map, 32-bit for a float one; rows from the
// top, tightly packed. Half texels are exact, so the GPU reads the very values of the file.
std::vector<std::byte> gpuTexelBytes(const DisplacementMap& map);
// Bytes of gpuTexelBytes(map) (width * height * channels * bytes per channel): what the map
// keeps resident on the device, without mip levels.
std::uint64_t gpuResidentBytes(const DisplacementMap& map);

// The nearest half to value (round to nearest even), as a float; +-inf past the half range.
float roundToHalf(float value);
// Rounds every texel to its nearest half, so a half map holds only exact halves.
void roundTexelsToHalf(DisplacementMap& map);

}  // namespace tb::displacement
