#include "core/mesh/mesh_copies.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tb::mesh {

Mesh translatedCopies(const Mesh& mesh, int copies, double step_extents) {
  if (copies < 1) throw std::invalid_argument("translatedCopies: copies must be >= 1");
  if (!(step_extents > 1))
    throw std::invalid_argument("translatedCopies: step_extents must be > 1");
  Vec3d lo = mesh.positions.empty() ? Vec3d{} : mesh.positions.front(), hi = lo;
  for (const Vec3d& p : mesh.positions) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-6});
  const double step = step_extents * extent;
  const int columns = int(std::ceil(std::sqrt(double(copies))));

  Mesh out;
  out.source = mesh.source + " x" + std::to_string(copies);
  out.normals_computed = mesh.normals_computed;
  out.tags.boundary = mesh.tags.boundary;
  out.tags.boundary_from_tag = mesh.tags.boundary_from_tag;
  out.tags.fvar_propagate_corners = mesh.tags.fvar_propagate_corners;
  out.tags.smooth_triangles = mesh.tags.smooth_triangles;
  out.tags.crease_method = mesh.tags.crease_method;
  for (int c = 0; c < copies; ++c) {
    const Vec3d offset{step * (c % columns), step * (c / columns), 0};
    const uint32_t position_base = uint32_t(out.positions.size());
    const int32_t normal_base = int32_t(out.normals.size());
    const int32_t uv_base = int32_t(out.uvs.size());
    const uint32_t face_base = uint32_t(out.faceCount());
    for (const Vec3d& p : mesh.positions) out.positions.push_back(p + offset);
    out.normals.insert(out.normals.end(), mesh.normals.begin(), mesh.normals.end());
    out.uvs.insert(out.uvs.end(), mesh.uvs.begin(), mesh.uvs.end());
    const uint32_t corner_base = uint32_t(out.corner_positions.size());
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      out.face_offsets.push_back(corner_base + mesh.face_offsets[f + 1]);
    }
    for (uint32_t p : mesh.corner_positions) out.corner_positions.push_back(position_base + p);
    for (int32_t n : mesh.corner_normals) out.corner_normals.push_back(n < 0 ? n : normal_base + n);
    for (int32_t t : mesh.corner_uvs) out.corner_uvs.push_back(t < 0 ? t : uv_base + t);
    out.face_lines.insert(out.face_lines.end(), mesh.face_lines.begin(), mesh.face_lines.end());
    for (const Crease& crease : mesh.tags.creases) {
      out.tags.creases.push_back(
          {position_base + crease.v0, position_base + crease.v1, crease.sharpness});
    }
    for (const Corner& corner : mesh.tags.corners) {
      out.tags.corners.push_back({position_base + corner.vertex, corner.sharpness});
    }
    for (uint32_t hole : mesh.tags.holes) out.tags.holes.push_back(face_base + hole);
  }
  return out;
}

}  // namespace tb::mesh
