#include "core/mesh/triangulate.h"

#include <algorithm>

namespace tb::mesh {

Triangulation fanTriangulate(const Mesh& mesh) {
  Triangulation result;
  Mesh& out = result.mesh;
  out.source = mesh.source;
  out.positions = mesh.positions;
  out.normals = mesh.normals;
  out.uvs = mesh.uvs;
  out.tags = mesh.tags;
  out.tags.holes.clear();  // face ids change: re-added below for every triangle of a hole
  out.normals_computed = mesh.normals_computed;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t begin = mesh.face_offsets[f];
    const uint32_t n = mesh.faceSize(f);
    if (n > 3) ++result.polygons_split;
    for (uint32_t k = 1; k + 1 < n; ++k) {
      const uint32_t corners[3] = {begin, begin + k, begin + k + 1};
      uint32_t positions[3];
      int32_t normals[3], uvs[3];
      for (int i = 0; i < 3; ++i) {
        positions[i] = mesh.corner_positions[corners[i]];
        normals[i] = mesh.corner_normals[corners[i]];
        uvs[i] = mesh.corner_uvs[corners[i]];
      }
      if (std::find(mesh.tags.holes.begin(), mesh.tags.holes.end(), uint32_t(f)) !=
          mesh.tags.holes.end()) {
        out.tags.holes.push_back(uint32_t(out.faceCount()));
      }
      out.addFace(positions, normals, uvs, mesh.face_lines[f]);
      result.source_face.push_back(uint32_t(f));
    }
  }
  return result;
}

std::vector<std::string> triangulationWarnings(const Triangulation& triangulation) {
  std::vector<std::string> warnings;
  if (triangulation.polygons_split > 0) {
    warnings.push_back(std::to_string(triangulation.polygons_split) +
                       " polygons with more than 3 vertices were fan-triangulated");
  }
  if (triangulation.mesh.normals_computed) {
    warnings.push_back("the mesh has no normals: angle-weighted smooth normals were computed");
  }
  return warnings;
}

}  // namespace tb::mesh
