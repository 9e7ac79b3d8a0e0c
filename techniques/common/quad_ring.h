// Ordered 1-rings of a manifold quad mesh, shared by ACC and Gregory ACC: around vertex v
// the ring alternates edge neighbours e_i and face diagonals f_i (face f_i is
// v -> e_i -> f_i -> e_{i+1} in its own order); a boundary ring runs from boundary edge e_0
// to e_{n-1}. The stored start is fixed per vertex, so every face sums a ring in the same
// order (docs/ARCHITECTURE.md §5 rule 1). A crease or corner vertex has one ring per sector;
// ring r < the position count is vertex r's first (docs/derivations/acc_gregory.md).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::techniques {

struct CreasePreparation;

struct VertexRing {
  uint32_t vertex = 0;      // the centre's position index
  uint32_t offset = 0;      // into QuadRings::edge_neighbours / diagonals
  uint32_t valence = 0;     // n: edges at the vertex (in the sector)
  uint32_t face_count = 0;  // n on the interior, n - 1 on a boundary or sector
  bool boundary = false;    // a mesh boundary or a sector between sharp edges
  bool corner = false;      // the limit interpolates the vertex (a sharp corner)
};

struct QuadRings {
  std::vector<VertexRing> rings;          // per position, then extra sectors; valence 0 when unused
  std::vector<uint32_t> edge_neighbours;  // e_i, `valence` entries per vertex
  std::vector<uint32_t> diagonals;        // f_i, `valence` entries (last unused on a boundary)
  // Per face, per corner k: the ring slot i of the face at corner k's vertex, so that
  // e_i is corner k+1, f_i is corner k+2 and e_{i+1} is corner k+3.
  std::vector<std::array<uint32_t, 4>> face_slots;
  // Per face, per corner k: the ring (the sector of corner k's vertex) the face lies in.
  std::vector<std::array<uint32_t, 4>> face_rings;

  uint32_t e(uint32_t v, uint32_t i) const {
    const VertexRing& r = rings[v];
    return edge_neighbours[r.offset + i % r.valence];
  }
  uint32_t f(uint32_t v, uint32_t i) const {
    const VertexRing& r = rings[v];
    return diagonals[r.offset + i % r.valence];
  }
};

// Builds the rings of an all-quad, edge- and vertex-manifold, consistently oriented
// mesh. Throws UnsupportedInput "<technique>: <element> <rule>" naming the first face
// or vertex that breaks a rule: a non-quad face, a degenerate face, an edge used
// twice in one direction (non-manifold or flipped), a vertex whose faces form more
// than one fan, valence above max_valence. With `creases`, built over creases->control:
// rings split at its sharp edges and corners marked from its vertex kinds; without, a
// boundary vertex of one face is a corner (edge-and-corner interpolation).
QuadRings buildQuadRings(const mesh::Mesh& mesh, const std::string& technique, uint32_t max_valence,
                         const CreasePreparation* creases = nullptr);

// Throws UnsupportedInput "<technique>: ..." for a mesh without faces, its first face that is
// not a quad ("face 3 (line 12) has 5 vertices; <why_quads>") and its first edge shared by
// three or more faces ("edge 4-7 is shared by 3 faces; <why_manifold>").
void requireManifoldQuads(const mesh::Mesh& mesh, const std::string& technique,
                          const std::string& why_quads, const std::string& why_manifold);

// "vertex 12 (0.5, 1, 0)" for error messages.
std::string describeVertex(const mesh::Mesh& mesh, uint32_t vertex);

}  // namespace tb::techniques
