#include "reference/triangle_mesh_ref.h"

#include <algorithm>

#include "core/mesh/triangulate.h"

namespace tb::ref {

std::vector<Triangle> fanTriangles(const mesh::Mesh& mesh) {
  const mesh::Triangulation triangulated = mesh::fanTriangulate(mesh);
  std::vector<Triangle> triangles(triangulated.mesh.faceCount());
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto corners = triangulated.mesh.facePositions(t);
    triangles[t] = {corners[0], corners[1], corners[2]};
  }
  return triangles;
}

double boundingBoxDiagonal(std::span<const mesh::Vec3d> positions) {
  if (positions.empty()) return 0;
  mesh::Vec3d lo = positions.front(), hi = positions.front();
  for (const mesh::Vec3d& p : positions) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  }
  return length(hi - lo);
}

}  // namespace tb::ref
