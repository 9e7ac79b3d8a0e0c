#include "techniques/common/triangle_records.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <utility>

#include "core/mesh/topology.h"

namespace tb::techniques {
namespace {

bool lexLess(const mesh::Vec3d& a, const mesh::Vec3d& b) {
  for (int k = 0; k < 3; ++k) {
    if (a[k] != b[k]) return a[k] < b[k];
  }
  return false;
}

// Face corner indices sorted by position (then position index): both faces of a
// shared edge see its two ends in the same order, because welded positions are
// bitwise equal.
std::array<uint32_t, 3> canonicalOrder(const mesh::Mesh& mesh, size_t face) {
  const auto pos = mesh.facePositions(face);
  std::array<uint32_t, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const mesh::Vec3d& pa = mesh.positions[pos[a]];
    const mesh::Vec3d& pb = mesh.positions[pos[b]];
    if (lexLess(pa, pb)) return true;
    if (lexLess(pb, pa)) return false;
    return pos[a] < pos[b];
  });
  return order;
}

struct EdgeUse {
  uint32_t face;
  uint32_t corner_a, corner_b;  // face corners (0..2) at the edge's lower, higher welded end
};

using EdgeKey = std::pair<uint32_t, uint32_t>;  // welded positions, lower first

// The mesh seen through its welding: corners by welded position, normals by index.
struct WeldedMesh {
  const mesh::Mesh& mesh;
  mesh::Welding weld;
  uint32_t weldedAt(size_t face, uint32_t corner) const {
    return weld.canonical[mesh.corner_positions[mesh.face_offsets[face] + corner]];
  }
  uint32_t normalAt(size_t face, uint32_t corner) const {
    return uint32_t(mesh.corner_normals[mesh.face_offsets[face] + corner]);
  }
  mesh::Vec3d unitNormal(uint32_t index) const { return normalize(mesh.normals[index]); }
};

// Every edge by welded position pair, whether it is split (its faces disagree on the unit
// normal at either end), and the mean edge length (world units).
struct EdgeTable {
  std::map<EdgeKey, std::vector<EdgeUse>> uses;
  std::map<EdgeKey, bool> split;
  double mean_edge = 0;
};

EdgeTable collectEdges(const WeldedMesh& w, TriangleRecords* build) {
  EdgeTable table;
  for (size_t f = 0; f < w.mesh.faceCount(); ++f) {
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t a = k, b = (k + 1) % 3;
      if (w.weldedAt(f, b) < w.weldedAt(f, a)) std::swap(a, b);
      table.uses[{w.weldedAt(f, a), w.weldedAt(f, b)}].push_back({uint32_t(f), a, b});
    }
  }
  double edge_length_sum = 0;
  for (const auto& [key, uses] : table.uses) {
    bool differs = false;
    for (const EdgeUse& use : uses) {
      differs = differs ||
                !(w.unitNormal(w.normalAt(use.face, use.corner_a)) ==
                  w.unitNormal(w.normalAt(uses[0].face, uses[0].corner_a))) ||
                !(w.unitNormal(w.normalAt(use.face, use.corner_b)) ==
                  w.unitNormal(w.normalAt(uses[0].face, uses[0].corner_b)));
    }
    table.split[key] = differs && uses.size() >= 2;
    build->split_edges += table.split[key] ? 1 : 0;
    build->boundary_edges += uses.size() == 1 ? 1 : 0;
    edge_length_sum += length(w.mesh.positions[key.second] - w.mesh.positions[key.first]);
  }
  table.mean_edge = table.uses.empty() ? 0.0 : edge_length_sum / double(table.uses.size());
  return table;
}

// Seed 003's geometry normal: per position, the distinct unit normals met there (equal
// normals count once, so an edge whose faces agree adds nothing) summed in sorted order
// and renormalised; the same value for every face at that position. Appends them to
// build->normals and returns each welded position's index there (UINT32_MAX: unused).
std::vector<uint32_t> appendGeometryNormals(const WeldedMesh& w, TriangleRecords* build) {
  std::vector<std::vector<mesh::Vec3d>> distinct(w.mesh.positions.size());
  for (size_t f = 0; f < w.mesh.faceCount(); ++f) {
    for (uint32_t k = 0; k < 3; ++k) {
      auto& list = distinct[w.weldedAt(f, k)];
      const mesh::Vec3d n = w.unitNormal(w.normalAt(f, k));
      if (std::find(list.begin(), list.end(), n) == list.end()) list.push_back(n);
    }
  }
  std::vector<uint32_t> geometry_index(w.mesh.positions.size(), UINT32_MAX);
  for (size_t v = 0; v < distinct.size(); ++v) {
    if (distinct[v].empty()) continue;
    std::sort(distinct[v].begin(), distinct[v].end(), lexLess);
    mesh::Vec3d sum{};
    for (const mesh::Vec3d& n : distinct[v]) sum = sum + n;
    geometry_index[v] = uint32_t(build->normals.size());
    build->normals.push_back(normalize(sum));
    ++build->geometry_normal_count;
  }
  return geometry_index;
}

// Seed 003's rounding scale of canonical edge e of record r (see kDefaultRounding); 1
// without rounding.
double roundingScale(const WeldedMesh& w, const TriangleRecords& build,
                     const TriangleRecordOptions& options, const TriangleRecord& r, int e,
                     bool flagged, const EdgeKey& key, double mean_edge) {
  if (options.rounding <= 0) return 1.0;
  const mesh::Vec3d na = normalize(
      build.normals[flagged ? r.geometry_normal[kEdgeEnds[e][0]] : r.normal[kEdgeEnds[e][0]]]);
  const mesh::Vec3d nb = normalize(
      build.normals[flagged ? r.geometry_normal[kEdgeEnds[e][1]] : r.normal[kEdgeEnds[e][1]]]);
  const double len = length(w.mesh.positions[key.second] - w.mesh.positions[key.first]);
  const double c = options.rounding * mean_edge;
  return len > 0 ? std::min(1.0, std::max(0.0, 1.0 - dot(na, nb)) * c / len) : 1.0;
}

// The flags, AEN neighbour normals and scale of canonical edge e of face f's record.
void fillEdge(const WeldedMesh& w, const EdgeTable& edges, const TriangleRecords& build,
              const TriangleRecordOptions& options, size_t f, const std::array<uint32_t, 3>& order,
              int e, TriangleRecord* r) {
  const uint32_t ca = order[kEdgeEnds[e][0]], cb = order[kEdgeEnds[e][1]];
  const uint32_t wa = w.weldedAt(f, ca), wb = w.weldedAt(f, cb);
  const EdgeKey key = std::make_pair(std::min(wa, wb), std::max(wa, wb));
  const std::vector<EdgeUse>& uses = edges.uses.at(key);
  const bool flagged = options.geometry_normals && edges.split.at(key);
  const bool boundary = uses.size() == 1;
  for (int end = 0; end < 2; ++end) {
    const uint32_t label = uint32_t(kEdgeEnds[e][end]);
    if (flagged) r->flags[label] |= 1u << e;
    if (boundary) r->flags[label] |= 1u << (3 + e);
    // AEN: the other face of a manifold edge, at the same welded position.
    r->other_normal[e][end] = r->normal[label];
    if (uses.size() == 2) {
      const EdgeUse& other = uses[0].face == f ? uses[1] : uses[0];
      const uint32_t welded = end == 0 ? wa : wb;
      const uint32_t corner =
          w.weldedAt(other.face, other.corner_a) == welded ? other.corner_a : other.corner_b;
      r->other_normal[e][end] = w.normalAt(other.face, corner);
    }
  }
  double scale = roundingScale(w, build, options, *r, e, flagged, key, edges.mean_edge);
  if (options.boundary_flags && boundary) scale = 0.0;
  r->edge_scale[e] = scale;
}

// Face f's record: corners in canonical order, then its three edges.
TriangleRecord buildRecord(const WeldedMesh& w, const EdgeTable& edges,
                           const std::vector<uint32_t>& geometry_index,
                           const TriangleRecords& build, const TriangleRecordOptions& options,
                           size_t f) {
  TriangleRecord r{};
  const auto order = canonicalOrder(w.mesh, f);
  for (int i = 0; i < 3; ++i) {
    r.perm[i] = order[i];
    r.position[i] = w.mesh.corner_positions[w.mesh.face_offsets[f] + order[i]];
    r.normal[i] = w.normalAt(f, order[i]);
    r.geometry_normal[i] = geometry_index[w.weldedAt(f, order[i])];
    r.flags[i] = 0;
  }
  for (int e = 0; e < 3; ++e) fillEdge(w, edges, build, options, f, order, e, &r);
  return r;
}

}  // namespace

TriangleRecords buildTriangleRecords(const mesh::Mesh& mesh, const TriangleRecordOptions& options) {
  TriangleRecords build;
  build.normals = mesh.normals;
  const WeldedMesh welded{mesh, mesh::weldByPosition(mesh)};
  const EdgeTable edges = collectEdges(welded, &build);
  const std::vector<uint32_t> geometry_index = appendGeometryNormals(welded, &build);
  build.records.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    build.records[f] = buildRecord(welded, edges, geometry_index, build, options, f);
  }
  return build;
}

}  // namespace tb::techniques
