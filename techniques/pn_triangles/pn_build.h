// Per-patch data of `pn_triangles`: canonical corner order, geometry normals and edge
// flags (seed 003), boundary flags (seed 003), PN-AEN neighbour normals (McDonald &
// Kilgard 2010) and per-edge rounding scales (seed 003). The same records feed the CPU
// evaluators and the GPU program (shaders/pn_triangles/pn.tesc reads them by index).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"
#include "techniques/pn_triangles/pn_eval.h"

namespace tb::pn_triangles {

struct PnOptions {
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

// One patch, 24 words on the GPU (PnRecordWord). Indices are in canonical label order:
// label 0 < 1 < 2 sorted by position, ties by position index.
struct PnRecord {
  std::array<uint32_t, 3> perm;             // label -> face corner (gl_TessCoord component)
  std::array<uint32_t, 3> position;         // into Mesh::positions
  std::array<uint32_t, 3> normal;           // shading normal, into PnBuild::normals
  std::array<uint32_t, 3> geometry_normal;  // into PnBuild::normals
  // Seed 003's per-vertex flags: bit e (0..2) set when canonical edge e is a split edge
  // that uses geometry normals; bit 3 + e when edge e is an unshared boundary edge.
  std::array<uint32_t, 3> flags;
  std::array<std::array<uint32_t, 2>, 3> other_normal;  // AEN: neighbour's normal per edge end
  std::array<double, 3> edge_scale;  // 1, or 0 on flagged boundaries, or rounding
};

enum PnRecordWord : uint32_t {
  kWordPerm = 0,
  kWordPosition = 3,
  kWordNormal = 6,
  kWordGeometryNormal = 9,
  kWordFlags = 12,
  kWordOtherNormal = 15,
  kWordEdgeScale = 21,
  kRecordWords = 24,
};

struct PnBuild {
  std::vector<Vec3d> normals;     // the mesh's normals as read, then the geometry normals (unit)
  std::vector<PnRecord> records;  // one per triangle
  size_t split_edges = 0;         // shared edges whose faces disagree on a normal
  size_t boundary_edges = 0;      // edges with one face after welding by position
  size_t geometry_normal_count = 0;
};

// `mesh` must be all triangles with normals on every corner.
PnBuild buildPnRecords(const Mesh& mesh, const PnOptions& options);

// The evaluator input of patch p in scalar T; cast turns a Vec3d into Vec3T<T>. Reads
// exactly what shaders/pn_triangles/pn.tesc reads, and normalises the same normals.
template <class T, class Cast>
PnInput<T> recordInput(const Mesh& mesh, const PnBuild& build, const PnOptions& options,
                       size_t patch, Cast cast) {
  const PnRecord& r = build.records[patch];
  PnInput<T> in;
  for (int i = 0; i < 3; ++i) {
    in.position[i] = cast(mesh.positions[r.position[i]]);
    in.normal[i] = normalizeInOrder(cast(build.normals[r.normal[i]]));
  }
  for (int e = 0; e < 3; ++e) {
    const int a = kEdgeEnds[e][0], b = kEdgeEnds[e][1];
    const bool flagged = ((r.flags[a] & r.flags[b]) & (1u << e)) != 0;
    for (int end = 0; end < 2; ++end) {
      const int label = kEdgeEnds[e][end];
      in.edge_own[e][end] = flagged
                                ? normalizeInOrder(cast(build.normals[r.geometry_normal[label]]))
                                : in.normal[label];
      // The shader reads the neighbour's normal only for PN-AEN.
      in.edge_other[e][end] = options.aen
                                  ? normalizeInOrder(cast(build.normals[r.other_normal[e][end]]))
                                  : in.edge_own[e][end];
    }
    in.edge_scale[e] = T(r.edge_scale[e]);
  }
  in.aen = options.aen;
  in.use_scale = options.boundary_flags || options.rounding > 0;
  return in;
}

// The evaluator input of patch p, with the float or double data of `build`.
PnInput<float> recordInputFloat(const Mesh& mesh, const PnBuild& build, const PnOptions& options,
                                size_t patch);
PnInput<double> recordInputDouble(const Mesh& mesh, const PnBuild& build, const PnOptions& options,
                                  size_t patch);

// GPU storage buffers 1..3: positions (vec4), normals (vec4), records (24 words each).
std::vector<std::vector<uint32_t>> pnStorageBuffers(const Mesh& mesh, const PnBuild& build);

}  // namespace tb::pn_triangles
