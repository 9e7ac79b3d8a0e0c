// The rules a displacement map obeys in memory, checked before a write and after a read.
#pragma once

#include <string>

#include "core/displacement/displacement_map.h"

namespace tb::displacement {

// Throws InputError(file, element, rule) for the first broken rule: a width or height of 0 or
// above kMaxDisplacementSide, a texel count other than width * height * channels, a tile
// layout whose tiles do not fit the atlas (or a zero field, or 2 * border >= tile_size), a
// NaN or infinite texel, and in a half map a texel that is not an exact half.
void validateDisplacementMap(const DisplacementMap& map, const std::string& file);

}  // namespace tb::displacement
