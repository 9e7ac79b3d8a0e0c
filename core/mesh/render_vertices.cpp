#include "core/mesh/render_vertices.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <array>

namespace tb::mesh {

RenderVertices buildRenderVertices(const Mesh& mesh) {
  RenderVertices result;
  const size_t corners = mesh.corner_positions.size();
  std::vector<std::array<int64_t, 3>> keys(corners);
  for (size_t c = 0; c < corners; ++c) {
    keys[c] = {mesh.corner_positions[c], mesh.corner_normals[c], mesh.corner_uvs[c]};
  }
  result.corner_vertex.resize(corners);
  if (corners == 0) return result;
  result.vertex_count = meshopt_generateVertexRemap(result.corner_vertex.data(), nullptr, corners,
                                                    keys.data(), corners, sizeof(keys[0]));
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(corners);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t begin = mesh.face_offsets[f], n = mesh.faceSize(f);
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t a = result.corner_vertex[begin + k];
      const uint32_t b = result.corner_vertex[begin + (k + 1) % n];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  result.edge_count = std::unique(edges.begin(), edges.end()) - edges.begin();
  return result;
}

uint64_t triangleControlMeshBytes(const Mesh& mesh) {
  return buildRenderVertices(mesh).vertex_count * kRenderVertexBytes +
         mesh.faceCount() * 3 * kIndexBytes;
}

}  // namespace tb::mesh
