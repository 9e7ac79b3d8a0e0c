// Axis-aligned bounds of a mesh: the box camera paths are placed in, and its diagonal, the
// length unit of distance-based policies and margins (world units).
#pragma once

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"

namespace tb::mesh {

// Axis-aligned bounding box, world units; min <= max component-wise.
struct Aabb {
  Vec3d min{0, 0, 0};
  Vec3d max{0, 0, 0};
};

// The bounding box of the mesh's positions; the unit cube [-1, 1]^3 when it has none (a
// simulation's scenario).
Aabb boundsOf(const Mesh& mesh);

// |max - min|: the box's diagonal, world units.
inline double diagonalOf(const Aabb& box) { return length(box.max - box.min); }

}  // namespace tb::mesh
