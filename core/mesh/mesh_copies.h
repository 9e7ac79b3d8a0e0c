// Disjoint translated copies of one mesh in one mesh: the scaling benchmarks grow the
// work this way, so the patch mix (regular, extraordinary, boundary) stays constant
// while the patch count grows.
#pragma once

#include "core/mesh/mesh.h"

namespace tb::mesh {

// `copies` (>= 1) copies of `mesh` on a square grid in the xy plane, each moved by a
// whole number of grid steps of `step_extents` (> 1, default 2) times the mesh's largest
// bounding-box extent, so no two copies touch. Every attribute (normals, UVs, tags, source lines)
// is repeated with its indices offset; copy 0 keeps the original coordinates. Throws
// std::invalid_argument for copies < 1 or step_extents <= 1.
Mesh translatedCopies(const Mesh& mesh, int copies, double step_extents = 2);

}  // namespace tb::mesh
