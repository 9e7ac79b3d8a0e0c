// Turns captured TES output (each primitive as its vertices' gl_TessCoord bits) into
// unique points plus index primitives, welding by bitwise coordinate equality.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "core/tess/tessellator.h"

namespace tb::gpu {

using CoordBits = std::array<uint32_t, 3>;  // gl_TessCoord.xyz as float bits

// vertices_per_primitive: 3 for triangles, 2 for isolines, 1 for point mode (then only
// points are filled). Points keep the order of their first appearance; coincident vertices
// become one point, so a degenerate triangle may repeat an index. `culled` stays false.
tess::Tessellation weldCapture(std::span<const CoordBits> vertices,
                               uint32_t vertices_per_primitive);

}  // namespace tb::gpu
