// Which world axis a picture shows vertical (docs/REPORTS.md, "Pictures"). OBJ files
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

// The up axis of a mesh, from its positions: z when the shape looks symmetric about z, by
// either of two measures of spread per coordinate, the variance about the mean or the
// bounding box's extent: the same along x and y (within kUpAxisSymmetryTolerance of the
// larger) and different along z (by more than kUpAxisDistinctTolerance of the x-y mean);
// y (the OBJ convention) otherwise, and for fewer than 2 positions. A surface of revolution
// about z, a pyramid, a tent or a cube standing on the x-y plane passes; a shape symmetric
// about y (a torus lying in x-z) or about no axis does not. Deterministic (sums in position
// order). The bundled z-up shapes: catmark_pawn, tri_pawn, catmark_pyramid(_creases1),
// catmark_tent_creases1, catmark_cube(_corner3, _creases1), loop_cube_creases1,
// cylinder_seam (and full_suite/pole64 and the production pawns).
UpAxis detectUpAxis(std::span<const mesh::Vec3d> positions);

inline constexpr double kUpAxisSymmetryTolerance = 0.01;
inline constexpr double kUpAxisDistinctTolerance = 0.1;

}  // namespace tb::pictures
