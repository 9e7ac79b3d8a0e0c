#include "reference/mesh_checks.h"

#include <algorithm>
#include <cmath>

#include "core/mesh/input_error.h"
#include "reference/face_domain.h"

namespace tb::ref {

void checkFinitePositions(std::span<const mesh::Vec3d> positions, const std::string& source) {
  for (size_t i = 0; i < positions.size(); ++i) {
    const mesh::Vec3d& p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw mesh::InputError(source, "vertex " + std::to_string(i), "coordinate is not finite");
    }
  }
}

void checkTriangleCorners(std::span<const std::array<uint32_t, 3>> triangles, size_t vertex_count,
                          const std::string& source) {
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (uint32_t corner : triangles[t]) {
      if (corner >= vertex_count) {
        throw mesh::InputError(source, "triangle " + std::to_string(t),
                               "corner index " + std::to_string(corner) + " is out of range (" +
                                   std::to_string(vertex_count) + " vertices)");
      }
    }
  }
}

void checkFaceIndex(const mesh::Mesh& mesh, size_t face) {
  if (face >= mesh.faceCount()) {
    throw mesh::InputError(mesh.source, "face " + std::to_string(face),
                           "index out of range (" + std::to_string(mesh.faceCount()) + " faces)");
  }
}

void checkInsideFaceDomain(const mesh::Mesh& mesh, size_t face, osd::Scheme scheme,
                           mesh::Vec2d uv) {
  if (!insideFaceDomain(scheme, int(mesh.faceSize(face)), uv)) {
    throw mesh::InputError(mesh.source, mesh::describeFace(mesh, face),
                           "(u, v) = (" + std::to_string(uv.x) + ", " + std::to_string(uv.y) +
                               ") is outside the face's parameter domain");
  }
}

std::map<std::pair<uint32_t, uint32_t>, double> creaseSharpnessByEdge(const mesh::Mesh& mesh) {
  std::map<std::pair<uint32_t, uint32_t>, double> edges;
  for (const mesh::Crease& crease : mesh.tags.creases) {
    edges[std::minmax(crease.v0, crease.v1)] = crease.sharpness;
  }
  return edges;
}

}  // namespace tb::ref
