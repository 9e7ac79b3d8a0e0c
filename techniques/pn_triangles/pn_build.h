// The PN evaluator's input read from the shared per-triangle records
// (techniques/common/triangle_records.h), and the GPU storage buffers of
// shaders/pn_triangles/pn.tesc, which reads the same records by index.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh/mesh.h"
#include "techniques/common/triangle_records.h"
#include "techniques/pn_triangles/pn_eval.h"

namespace tb::pn_triangles {

// The evaluator input of patch p in scalar T; cast turns a Vec3d into Vec3T<T>. Reads
// exactly what shaders/pn_triangles/pn.tesc reads, and normalises the same normals.
template <class T, class Cast>
PnInput<T> recordInput(const mesh::Mesh& mesh, const techniques::TriangleRecords& build,
                       const techniques::TriangleRecordOptions& options, size_t patch, Cast cast) {
  const techniques::TriangleRecord& r = build.records[patch];
  PnInput<T> in;
  for (int i = 0; i < 3; ++i) {
    in.position[i] = cast(mesh.positions[r.position[i]]);
    in.normal[i] = normalizeInOrder(cast(build.normals[r.normal[i]]));
  }
  for (int e = 0; e < 3; ++e) {
    const int a = techniques::kEdgeEnds[e][0], b = techniques::kEdgeEnds[e][1];
    const bool flagged = ((r.flags[a] & r.flags[b]) & (1u << e)) != 0;
    for (int end = 0; end < 2; ++end) {
      const int label = techniques::kEdgeEnds[e][end];
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
PnInput<float> recordInputFloat(const mesh::Mesh& mesh, const techniques::TriangleRecords& build,
                                const techniques::TriangleRecordOptions& options, size_t patch);
PnInput<double> recordInputDouble(const mesh::Mesh& mesh, const techniques::TriangleRecords& build,
                                  const techniques::TriangleRecordOptions& options, size_t patch);

// GPU storage buffers 1..3: positions (vec4), normals (vec4), records (24 words each).
std::vector<std::vector<uint32_t>> pnStorageBuffers(const mesh::Mesh& mesh,
                                                    const techniques::TriangleRecords& build);

}  // namespace tb::pn_triangles
