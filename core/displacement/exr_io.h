// Displacement maps as OpenEXR files (scanline, ZIP compressed), read and written with the
// OpenEXR library. The format (channels, header attributes) is in docs/FORMATS.md,
// "Displacement maps". Every refusal is an InputError naming the file, the element and the
// rule in one line; a refused write leaves no file behind.
#pragma once

#include <optional>
#include <string>

#include "core/displacement/displacement_map.h"

namespace tb::displacement {

// Header attributes (string values; numbers in decimal) that carry the layout.
inline constexpr const char* kExrLayoutAttribute = "tessbench.layout";  // "tiles" or "uv"
inline constexpr const char* kExrTileSizeAttribute = "tessbench.tile_size";
inline constexpr const char* kExrTileBorderAttribute = "tessbench.tile_border";
inline constexpr const char* kExrTilesPerRowAttribute = "tessbench.tiles_per_row";
inline constexpr const char* kExrTileCountAttribute = "tessbench.tile_count";

// Largest width or height read or written, so a damaged header cannot ask for gigabytes.
inline constexpr std::uint32_t kMaxDisplacementSide = 16384;

// Throws InputError when the map is inconsistent (resolution 0, texel count, tile layout),
// holds a NaN or infinite texel, a half map holds a texel that is not an exact half, or the
// file cannot be written.
void writeDisplacementExr(const std::string& path, const DisplacementMap& map);

// expected: the kind the caller needs, or nullopt for either. Throws InputError for a missing,
// empty, truncated or non-EXR file, channels other than Y or R,G,B (or not the expected
// kind), mixed or integer channel types, a resolution of 0 or above kMaxDisplacementSide,
// missing or inconsistent layout attributes, and NaN or infinite texels.
DisplacementMap readDisplacementExr(const std::string& path,
                                    std::optional<DisplacementKind> expected = std::nullopt);

}  // namespace tb::displacement
