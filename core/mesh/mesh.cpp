#include "core/mesh/mesh.h"

#include <algorithm>

namespace tb::mesh {

bool Mesh::allFacesOfSize(uint32_t n) const {
  for (size_t f = 0; f < faceCount(); ++f) {
    if (faceSize(f) != n) return false;
  }
  return true;
}

uint32_t Mesh::maxFaceSize() const {
  uint32_t largest = 0;
  for (size_t f = 0; f < faceCount(); ++f) largest = std::max(largest, faceSize(f));
  return largest;
}

void Mesh::addFace(std::span<const uint32_t> positions_of_face, std::span<const int32_t> normal_ids,
                   std::span<const int32_t> uv_ids, uint32_t line) {
  for (size_t i = 0; i < positions_of_face.size(); ++i) {
    corner_positions.push_back(positions_of_face[i]);
    corner_normals.push_back(normal_ids.empty() ? -1 : normal_ids[i]);
    corner_uvs.push_back(uv_ids.empty() ? -1 : uv_ids[i]);
  }
  face_offsets.push_back(static_cast<uint32_t>(corner_positions.size()));
  face_lines.push_back(line);
}

std::string describeFace(const Mesh& mesh, size_t face) {
  std::string text = "face " + std::to_string(face);
  if (face < mesh.face_lines.size() && mesh.face_lines[face] != 0) {
    text += " (line " + std::to_string(mesh.face_lines[face]) + ")";
  }
  return text;
}

}  // namespace tb::mesh
