// Edge and vertex adjacency of a polygon mesh, built once and shared by the
// techniques (patch 1-rings, boundaries) and the measures (shared edges for cracks).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::mesh {

struct MeshEdge {
  uint32_t v0, v1;      // position indices, v0 < v1
  uint32_t first_face;  // into Topology::edge_faces
  uint32_t face_count;  // 1 = boundary, 2 = manifold interior, > 2 = non-manifold
};

struct Topology {
  std::vector<MeshEdge> edges;           // sorted by (v0, v1)
  std::vector<uint32_t> edge_faces;      // incident faces of each edge, ascending
  std::vector<uint32_t> corner_edges;    // per face corner k: the edge from corner k to k+1
  std::vector<uint32_t> valence;         // edges incident on each position
  std::vector<uint8_t> on_boundary;      // 1 when the position lies on a boundary edge
  std::vector<uint32_t> face_component;  // connected component of each face (by shared edges)
  uint32_t component_count = 0;

  std::span<const uint32_t> facesOfEdge(size_t e) const {
    return {edge_faces.data() + edges[e].first_face, edges[e].face_count};
  }
  size_t boundaryEdgeCount() const;
  size_t nonManifoldEdgeCount() const;
  // Vertices whose valence differs from the regular one: `interior_regular` inside
  // (4 for quads, 6 for triangles), interior_regular / 2 + 1 on a boundary.
  // Isolated positions (valence 0) are not counted.
  std::vector<uint32_t> extraordinaryVertices(uint32_t interior_regular) const;
  // Index of edge (a, b) in `edges`, or -1 when the mesh has no such edge.
  int64_t findEdge(uint32_t a, uint32_t b) const;
};

Topology buildTopology(const Mesh& mesh);

// What a user should know about a mesh's connectivity before trusting its figures, one line
// each; empty for a mesh whose faces share edges. Today: a polygon soup (more than one face
// and no edge shared by two faces), where every face is its own surface, so a smooth
// technique's error against the limit reads 0 and says nothing (weld the duplicates first).
std::vector<std::string> connectivityWarnings(const Mesh& mesh, const Topology& topology);

// Canonical index per position: positions with bitwise-identical coordinates map
// to the lowest-numbered one (meshoptimizer's vertex remap). Triangle techniques
// use it to find edges shared across duplicated positions.
struct Welding {
  std::vector<uint32_t> canonical;  // per position
  size_t unique_count = 0;
};
Welding weldByPosition(const Mesh& mesh);

}  // namespace tb::mesh
