#include "harness/measures/common/cracks/crack_seams.h"

#include <algorithm>
#include <array>
#include <bit>
#include <map>
#include <tuple>
#include <vector>

#include "core/mesh/mesh.h"
#include "core/mesh/topology.h"
#include "harness/measures/common/cracks/cracks.h"

namespace tb::measures {
namespace {

// A face corner's attributes, bit for bit (absent: all ones): normal x, y, z, uv u, v.
using Attributes = std::array<uint64_t, 5>;

Attributes cornerAttributes(const mesh::Mesh& m, size_t corner) {
  Attributes a;
  a.fill(~uint64_t(0));
  const int32_t n = corner < m.corner_normals.size() ? m.corner_normals[corner] : -1;
  const int32_t t = corner < m.corner_uvs.size() ? m.corner_uvs[corner] : -1;
  if (n >= 0 && size_t(n) < m.normals.size()) {
    for (int k = 0; k < 3; ++k) a[size_t(k)] = std::bit_cast<uint64_t>(m.normals[size_t(n)][k]);
  }
  if (t >= 0 && size_t(t) < m.uvs.size()) {
    a[3] = std::bit_cast<uint64_t>(m.uvs[size_t(t)].x);
    a[4] = std::bit_cast<uint64_t>(m.uvs[size_t(t)].y);
  }
  return a;
}

// A face's use of an edge: the welded ends (lower first) and the attribute ids there.
struct EdgeUse {
  uint32_t lo, hi, id_lo, id_hi;
  bool operator<(const EdgeUse& o) const {
    return std::tie(lo, hi, id_lo, id_hi) < std::tie(o.lo, o.hi, o.id_lo, o.id_hi);
  }
};

}  // namespace

const char* toString(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::kSeam:
      return "seam";
    case EdgeKind::kBoundary:
      return "boundary";
    default:
      return "interior";
  }
}

void classifySeams(const mesh::Mesh& control, const mesh::Welding& welding,
                   SharedBoundaries* shared) {
  std::map<Attributes, uint32_t> ids;  // distinct attribute sets, numbered as met
  const size_t vertex_count = control.positions.size();
  std::vector<uint32_t> vertex_id(vertex_count, UINT32_MAX), vertex_raw(vertex_count, UINT32_MAX);
  std::vector<uint8_t> seam_vertex(vertex_count, 0);
  std::vector<EdgeUse> uses;
  for (size_t f = 0; f < control.faceCount(); ++f) {
    const uint32_t begin = control.face_offsets[f], size = control.faceSize(f);
    for (uint32_t k = 0; k < size; ++k) {
      const uint32_t corner = begin + k, next = begin + (k + 1) % size;
      const uint32_t raw = control.corner_positions[corner];
      const uint32_t w = welding.canonical.at(raw);
      const uint32_t id =
          ids.emplace(cornerAttributes(control, corner), uint32_t(ids.size())).first->second;
      if (vertex_id[w] == UINT32_MAX) vertex_id[w] = id, vertex_raw[w] = raw;
      if (vertex_id[w] != id || vertex_raw[w] != raw) seam_vertex[w] = 1;
      const uint32_t wn = welding.canonical.at(control.corner_positions[next]);
      const uint32_t id_next =
          ids.emplace(cornerAttributes(control, next), uint32_t(ids.size())).first->second;
      if (w == wn) continue;
      uses.push_back(w < wn ? EdgeUse{w, wn, id, id_next} : EdgeUse{wn, w, id_next, id});
    }
  }
  std::sort(uses.begin(), uses.end());
  std::vector<uint8_t> boundary_vertex(vertex_count, 0);
  std::vector<std::pair<uint32_t, uint32_t>> seam_edges;  // sorted
  for (size_t i = 0; i < uses.size();) {
    size_t j = i + 1;
    bool differs = false;
    for (; j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi; ++j) {
      differs = differs || uses[j].id_lo != uses[i].id_lo || uses[j].id_hi != uses[i].id_hi;
    }
    if (j - i == 1) boundary_vertex[uses[i].lo] = boundary_vertex[uses[i].hi] = 1;
    if (differs) seam_edges.emplace_back(uses[i].lo, uses[i].hi);
    i = j;
  }
  for (SharedEdge& edge : shared->edges) {
    const bool attribute_seam =
        std::binary_search(seam_edges.begin(), seam_edges.end(), std::make_pair(edge.v0, edge.v1));
    edge.kind = edge.seam || attribute_seam ? EdgeKind::kSeam : EdgeKind::kInterior;
  }
  for (SharedCorner& corner : shared->corners) {
    const uint32_t v = corner.vertex;
    corner.kind = v < vertex_count && seam_vertex[v]       ? EdgeKind::kSeam
                  : v < vertex_count && boundary_vertex[v] ? EdgeKind::kBoundary
                                                           : EdgeKind::kInterior;
  }
}

}  // namespace tb::measures
