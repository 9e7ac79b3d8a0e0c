// Per-triangle records shared by the triangle techniques (pn_triangles; phong's `edge`
// variant): canonical corner order, geometry normals and edge flags (seed 003), boundary
// flags (seed 003), PN-AEN neighbour normals (McDonald & Kilgard 2010) and per-edge
// rounding scales (seed 003). The same records feed the CPU evaluators and the GPU
// programs (shaders/pn_triangles/pn.tesc and shaders/phong/phong.tesc read them by index).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/vec.h"

namespace tb::techniques {

// Edges in canonical order: edge e joins labels kEdgeEnds[e][0] < kEdgeEnds[e][1].
inline constexpr int kEdgeEnds[3][2] = {{0, 1}, {0, 2}, {1, 2}};

struct TriangleRecordOptions {
  bool geometry_normals = false;  // shared normal per position on flagged (split) edges
  bool boundary_flags = false;    // unshared boundary edges are straight (T-junction fix)
  bool aen = false;               // PN-AEN edge points
  double rounding = 0;            // > 0: seed 003's rounding constant (see kRoundingNote)
};

// The rounding scale of an edge is min(1, (1 - N_i·N_j) × C / L), L the edge length and
// C = options.rounding × the mesh's mean edge length: long, nearly flat edges (N_i·N_j
// near 1) get straighter, short strongly curved ones keep the full PN bulge. Seed 003
// gives the shape "(1 - dot of the edge normals) × constant / edge length" and leaves the
// constant to the artist per material; tessbench's variant uses 4 mean edge lengths.
constexpr double kDefaultRounding = 4.0;

// One patch, 24 words on the GPU (TriangleRecordWord). Indices are in canonical label order:
// label 0 < 1 < 2 sorted by position, ties by position index.
struct TriangleRecord {
  std::array<uint32_t, 3> perm;             // label -> face corner (gl_TessCoord component)
  std::array<uint32_t, 3> position;         // into Mesh::positions
  std::array<uint32_t, 3> normal;           // shading normal, into TriangleRecords::normals
  std::array<uint32_t, 3> geometry_normal;  // into TriangleRecords::normals
  // Seed 003's per-vertex flags: bit e (0..2) set when canonical edge e is a split edge
  // that uses geometry normals; bit 3 + e when edge e is an unshared boundary edge.
  std::array<uint32_t, 3> flags;
  std::array<std::array<uint32_t, 2>, 3> other_normal;  // AEN: neighbour's normal per edge end
  std::array<double, 3> edge_scale;  // 1, or 0 on flagged boundaries, or rounding
};

enum TriangleRecordWord : uint32_t {
  kWordPerm = 0,
  kWordPosition = 3,
  kWordNormal = 6,
  kWordGeometryNormal = 9,
  kWordFlags = 12,
  kWordOtherNormal = 15,
  kWordEdgeScale = 21,
  kRecordWords = 24,
};

struct TriangleRecords {
  std::vector<mesh::Vec3d> normals;  // the mesh's normals as read, then the geometry normals (unit)
  std::vector<TriangleRecord> records;  // one per triangle
  size_t split_edges = 0;               // shared edges whose faces disagree on a normal
  size_t boundary_edges = 0;            // edges with one face after welding by position
  size_t geometry_normal_count = 0;
};

// `mesh` must be all triangles with normals on every corner.
TriangleRecords buildTriangleRecords(const mesh::Mesh& mesh, const TriangleRecordOptions& options);

}  // namespace tb::techniques
