// Which world axis a picture shows vertical (docs/ARCHITECTURE.md §4, "Pictures"). OBJ files
// are y-up by convention, but some bundled shapes (OpenSubdiv's pawn, pyramid and tent, the
// cylinder) are modelled z-up and lay on their side in a y-up view. The pictures turn the
// camera, never the data: a z-up asset is seen as if it were rotated to y-up.
#pragma once

#include <span>

#include "core/mesh/mesh.h"

namespace tb::pictures {

enum class UpAxis { kY, kZ };

// "y" or "z".
const char* toString(UpAxis up);

// The world direction shown upwards: (0, 1, 0) or (0, 0, 1).
mesh::Vec3d upVector(UpAxis up);

// The up axis of a mesh, from its positions: z when the positions' spread about their mean
// (the variance of each coordinate) is the same along x and y (within
// kUpAxisSymmetryTolerance of the larger) and differs along z (by more than
// kUpAxisDistinctTolerance of the x-y mean), i.e. z is the axis the shape is symmetric
// about (a surface of revolution about z, a pyramid or a tent standing on the x-y plane);
// y (the OBJ convention) otherwise, and for fewer than 2 positions. Deterministic: sums
// in position order. The bundled z-up shapes: catmark_pawn, tri_pawn, catmark_pyramid,
// catmark_pyramid_creases1, catmark_tent_creases1, cylinder_seam (and full_suite/pole64,
// production pawns); no y-up bundled shape passes the test.
UpAxis detectUpAxis(std::span<const mesh::Vec3d> positions);

inline constexpr double kUpAxisSymmetryTolerance = 0.01;
inline constexpr double kUpAxisDistinctTolerance = 0.1;

}  // namespace tb::pictures
