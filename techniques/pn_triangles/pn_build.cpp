#include "techniques/pn_triangles/pn_build.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <utility>

#include "core/mesh/topology.h"

namespace tb::pn_triangles {
namespace {

bool lexLess(const Vec3d& a, const Vec3d& b) {
  for (int k = 0; k < 3; ++k) {
    if (a[k] != b[k]) return a[k] < b[k];
  }
  return false;
}

// Face corner indices sorted by position (then position index): both faces of a
// shared edge see its two ends in the same order, because welded positions are
// bitwise equal.
std::array<uint32_t, 3> canonicalOrder(const Mesh& mesh, size_t face) {
  const auto pos = mesh.facePositions(face);
  std::array<uint32_t, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const Vec3d& pa = mesh.positions[pos[a]];
    const Vec3d& pb = mesh.positions[pos[b]];
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

}  // namespace

PnBuild buildPnRecords(const Mesh& mesh, const PnOptions& options) {
  PnBuild build;
  build.normals = mesh.normals;
  const Welding weld = weldByPosition(mesh);
  const size_t faces = mesh.faceCount();
  auto weldedAt = [&](size_t face, uint32_t corner) {
    return weld.canonical[mesh.corner_positions[mesh.face_offsets[face] + corner]];
  };
  auto normalAt = [&](size_t face, uint32_t corner) {
    return uint32_t(mesh.corner_normals[mesh.face_offsets[face] + corner]);
  };
  auto unitNormal = [&](uint32_t index) { return normalize(mesh.normals[index]); };

  // Edges by welded position pair.
  std::map<std::pair<uint32_t, uint32_t>, std::vector<EdgeUse>> edges;
  double edge_length_sum = 0;
  for (size_t f = 0; f < faces; ++f) {
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t a = k, b = (k + 1) % 3;
      if (weldedAt(f, b) < weldedAt(f, a)) std::swap(a, b);
      edges[{weldedAt(f, a), weldedAt(f, b)}].push_back({uint32_t(f), a, b});
    }
  }
  // A split edge: its faces disagree on the (unit) normal at either end.
  std::map<std::pair<uint32_t, uint32_t>, bool> split;
  for (const auto& [key, uses] : edges) {
    bool differs = false;
    for (const EdgeUse& use : uses) {
      differs = differs ||
                !(unitNormal(normalAt(use.face, use.corner_a)) ==
                  unitNormal(normalAt(uses[0].face, uses[0].corner_a))) ||
                !(unitNormal(normalAt(use.face, use.corner_b)) ==
                  unitNormal(normalAt(uses[0].face, uses[0].corner_b)));
    }
    split[key] = differs && uses.size() >= 2;
    build.split_edges += split[key] ? 1 : 0;
    build.boundary_edges += uses.size() == 1 ? 1 : 0;
    edge_length_sum += length(mesh.positions[key.second] - mesh.positions[key.first]);
  }
  const double mean_edge = edges.empty() ? 0.0 : edge_length_sum / double(edges.size());

  // Seed 003's geometry normal: per position, the distinct unit normals met there
  // (equal normals count once, so an edge whose faces agree adds nothing) summed in
  // sorted order and renormalised; the same value for every face at that position.
  std::vector<std::vector<Vec3d>> distinct(mesh.positions.size());
  for (size_t f = 0; f < faces; ++f) {
    for (uint32_t k = 0; k < 3; ++k) {
      auto& list = distinct[weldedAt(f, k)];
      const Vec3d n = unitNormal(normalAt(f, k));
      if (std::find(list.begin(), list.end(), n) == list.end()) list.push_back(n);
    }
  }
  std::vector<uint32_t> geometry_index(mesh.positions.size(), UINT32_MAX);
  for (size_t v = 0; v < distinct.size(); ++v) {
    if (distinct[v].empty()) continue;
    std::sort(distinct[v].begin(), distinct[v].end(), lexLess);
    Vec3d sum{};
    for (const Vec3d& n : distinct[v]) sum = sum + n;
    geometry_index[v] = uint32_t(build.normals.size());
    build.normals.push_back(normalize(sum));
    ++build.geometry_normal_count;
  }

  build.records.resize(faces);
  for (size_t f = 0; f < faces; ++f) {
    PnRecord& r = build.records[f];
    const auto order = canonicalOrder(mesh, f);
    for (int i = 0; i < 3; ++i) {
      r.perm[i] = order[i];
      r.position[i] = mesh.corner_positions[mesh.face_offsets[f] + order[i]];
      r.normal[i] = normalAt(f, order[i]);
      r.geometry_normal[i] = geometry_index[weldedAt(f, order[i])];
      r.flags[i] = 0;
    }
    for (int e = 0; e < 3; ++e) {
      const uint32_t ca = order[kEdgeEnds[e][0]], cb = order[kEdgeEnds[e][1]];
      const uint32_t wa = weldedAt(f, ca), wb = weldedAt(f, cb);
      const auto key = std::make_pair(std::min(wa, wb), std::max(wa, wb));
      const std::vector<EdgeUse>& uses = edges.at(key);
      const bool flagged = options.geometry_normals && split.at(key);
      const bool boundary = uses.size() == 1;
      for (int end = 0; end < 2; ++end) {
        const uint32_t label = uint32_t(kEdgeEnds[e][end]);
        if (flagged) r.flags[label] |= 1u << e;
        if (boundary) r.flags[label] |= 1u << (3 + e);
        // AEN: the other face of a manifold edge, at the same welded position.
        r.other_normal[e][end] = r.normal[label];
        if (uses.size() == 2) {
          const EdgeUse& other = uses[0].face == f ? uses[1] : uses[0];
          const uint32_t welded = end == 0 ? wa : wb;
          const uint32_t corner =
              weldedAt(other.face, other.corner_a) == welded ? other.corner_a : other.corner_b;
          r.other_normal[e][end] = normalAt(other.face, corner);
        }
      }
      double scale = 1.0;
      if (options.rounding > 0) {
        const Vec3d na = normalize(build.normals[flagged ? r.geometry_normal[kEdgeEnds[e][0]]
                                                         : r.normal[kEdgeEnds[e][0]]]);
        const Vec3d nb = normalize(build.normals[flagged ? r.geometry_normal[kEdgeEnds[e][1]]
                                                         : r.normal[kEdgeEnds[e][1]]]);
        const double len = length(mesh.positions[key.second] - mesh.positions[key.first]);
        const double c = options.rounding * mean_edge;
        scale = len > 0 ? std::min(1.0, std::max(0.0, 1.0 - dot(na, nb)) * c / len) : 1.0;
      }
      if (options.boundary_flags && boundary) scale = 0.0;
      r.edge_scale[e] = scale;
    }
  }
  return build;
}

PnInput<float> recordInputFloat(const Mesh& mesh, const PnBuild& build, const PnOptions& options,
                                size_t patch) {
  return recordInput<float>(mesh, build, options, patch,
                            [](const Vec3d& v) { return vecCast<float>(v); });
}

PnInput<double> recordInputDouble(const Mesh& mesh, const PnBuild& build, const PnOptions& options,
                                  size_t patch) {
  return recordInput<double>(mesh, build, options, patch, [](const Vec3d& v) { return v; });
}

std::vector<std::vector<uint32_t>> pnStorageBuffers(const Mesh& mesh, const PnBuild& build) {
  auto vec4s = [](const std::vector<Vec3d>& values) {
    std::vector<uint32_t> words;
    words.reserve(values.size() * 4 + 4);
    for (const Vec3d& v : values) {
      for (float x : {float(v.x), float(v.y), float(v.z), 1.0f}) {
        words.push_back(std::bit_cast<uint32_t>(x));
      }
    }
    if (words.empty()) words.assign(4, 0);  // a storage buffer may not be empty
    return words;
  };
  std::vector<uint32_t> records;
  records.reserve(build.records.size() * kRecordWords);
  for (const PnRecord& r : build.records) {
    for (uint32_t x : r.perm) records.push_back(x);
    for (uint32_t x : r.position) records.push_back(x);
    for (uint32_t x : r.normal) records.push_back(x);
    for (uint32_t x : r.geometry_normal) records.push_back(x);
    for (uint32_t x : r.flags) records.push_back(x);
    for (const auto& ends : r.other_normal) {
      for (uint32_t x : ends) records.push_back(x);
    }
    for (double s : r.edge_scale) records.push_back(std::bit_cast<uint32_t>(float(s)));
  }
  return {vec4s(mesh.positions), vec4s(build.normals), records};
}

}  // namespace tb::pn_triangles
