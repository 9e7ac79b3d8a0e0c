// The vertex buffer a plain renderer would upload: one vertex per distinct
// (position, normal, uv) combination used by a face corner, welded with
// meshoptimizer. Split normals and UV seams therefore duplicate vertices, as they
// do in any game's mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::mesh {

// float3 position + float3 normal + float2 uv.
constexpr uint64_t kRenderVertexBytes = 32;
constexpr uint64_t kIndexBytes = 4;  // 32-bit indices

struct RenderVertices {
  std::vector<uint32_t> corner_vertex;  // render vertex of each face corner
  size_t vertex_count = 0;
  // Distinct undirected edges between render vertices (a seam edge counts twice,
  // once per side, because its points are duplicated too).
  size_t edge_count = 0;
};

RenderVertices buildRenderVertices(const Mesh& mesh);

// Bytes of a triangle mesh's vertex and index buffers (every face must be a
// triangle): render vertices × 32 + triangles × 3 × 4.
uint64_t triangleControlMeshBytes(const Mesh& mesh);

}  // namespace tb::mesh
