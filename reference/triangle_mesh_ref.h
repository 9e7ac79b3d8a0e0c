// A borrowed triangle mesh (positions + corner indices) for the distance queries,
// and the conversions that produce one.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"

namespace tb::ref {

using Triangle = std::array<uint32_t, 3>;  // position indices, counter-clockwise

struct TriangleMeshRef {
  std::span<const mesh::Vec3d> positions;
  std::span<const Triangle> triangles;
};

// Position indices of a polygon mesh's triangles, fan-triangulated from each face's
// first corner (harness/mesh fanTriangulate; triangles pass through unchanged).
std::vector<Triangle> fanTriangles(const mesh::Mesh& mesh);

// Length of the diagonal of the axis-aligned bounding box (world units); 0 when empty.
// The relative tolerances and errors of the reference are fractions of it.
double boundingBoxDiagonal(std::span<const mesh::Vec3d> positions);

}  // namespace tb::ref
