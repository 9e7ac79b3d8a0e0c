#include "core/mesh/topology.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <numeric>
#include <tuple>

namespace tb::mesh {
namespace {

struct HalfEdge {
  uint32_t lo, hi, face, corner;
  bool operator<(const HalfEdge& other) const {
    return std::tie(lo, hi, face, corner) < std::tie(other.lo, other.hi, other.face, other.corner);
  }
};

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

void labelComponents(const Mesh& mesh, Topology* topology) {
  std::vector<uint32_t> parent(mesh.faceCount());
  std::iota(parent.begin(), parent.end(), 0u);
  for (size_t e = 0; e < topology->edges.size(); ++e) {
    const auto faces = topology->facesOfEdge(e);
    for (size_t k = 1; k < faces.size(); ++k) {
      parent[findRoot(parent, faces[k])] = findRoot(parent, faces[0]);
    }
  }
  // Number components in order of their first face, so labels are deterministic.
  std::vector<uint32_t> label(mesh.faceCount(), UINT32_MAX);
  topology->face_component.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const uint32_t root = findRoot(parent, uint32_t(f));
    if (label[root] == UINT32_MAX) label[root] = topology->component_count++;
    topology->face_component[f] = label[root];
  }
}

}  // namespace

size_t Topology::boundaryEdgeCount() const {
  return std::count_if(edges.begin(), edges.end(),
                       [](const MeshEdge& e) { return e.face_count == 1; });
}

size_t Topology::nonManifoldEdgeCount() const {
  return std::count_if(edges.begin(), edges.end(),
                       [](const MeshEdge& e) { return e.face_count > 2; });
}

std::vector<uint32_t> Topology::extraordinaryVertices(uint32_t interior_regular) const {
  std::vector<uint32_t> result;
  for (uint32_t v = 0; v < valence.size(); ++v) {
    if (valence[v] == 0) continue;
    const uint32_t regular = on_boundary[v] ? interior_regular / 2 + 1 : interior_regular;
    if (valence[v] != regular) result.push_back(v);
  }
  return result;
}

int64_t Topology::findEdge(uint32_t a, uint32_t b) const {
  const uint32_t lo = std::min(a, b), hi = std::max(a, b);
  auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(lo, hi),
                             [](const MeshEdge& e, const std::pair<uint32_t, uint32_t>& key) {
                               return std::tie(e.v0, e.v1) < std::tie(key.first, key.second);
                             });
  if (it == edges.end() || it->v0 != lo || it->v1 != hi) return -1;
  return it - edges.begin();
}

Topology buildTopology(const Mesh& mesh) {
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(mesh.corner_positions.size());
  for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
    const auto face = mesh.facePositions(f);
    for (uint32_t k = 0; k < face.size(); ++k) {
      const uint32_t a = face[k], b = face[(k + 1) % face.size()];
      half_edges.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  }
  std::sort(half_edges.begin(), half_edges.end());

  Topology topology;
  topology.corner_edges.resize(mesh.corner_positions.size());
  topology.valence.assign(mesh.positions.size(), 0);
  topology.on_boundary.assign(mesh.positions.size(), 0);
  for (size_t i = 0; i < half_edges.size();) {
    size_t j = i;
    MeshEdge edge{half_edges[i].lo, half_edges[i].hi, uint32_t(topology.edge_faces.size()), 0};
    const uint32_t edge_index = uint32_t(topology.edges.size());
    for (; j < half_edges.size() && half_edges[j].lo == edge.v0 && half_edges[j].hi == edge.v1;
         ++j) {
      const HalfEdge& h = half_edges[j];
      topology.corner_edges[mesh.face_offsets[h.face] + h.corner] = edge_index;
      // A face that uses the same edge twice counts once.
      if (edge.face_count == 0 || topology.edge_faces.back() != h.face) {
        topology.edge_faces.push_back(h.face);
        ++edge.face_count;
      }
    }
    topology.edges.push_back(edge);
    ++topology.valence[edge.v0];
    ++topology.valence[edge.v1];
    if (edge.face_count == 1) topology.on_boundary[edge.v0] = topology.on_boundary[edge.v1] = 1;
    i = j;
  }
  labelComponents(mesh, &topology);
  return topology;
}

Welding weldByPosition(const Mesh& mesh) {
  Welding welding;
  welding.canonical.resize(mesh.positions.size());
  if (mesh.positions.empty()) return welding;
  std::vector<uint32_t> remap(mesh.positions.size());
  welding.unique_count =
      meshopt_generateVertexRemap(remap.data(), nullptr, mesh.positions.size(),
                                  mesh.positions.data(), mesh.positions.size(), sizeof(Vec3d));
  // meshopt numbers unique positions densely in first-seen order; map each back to
  // the first position index that carries it.
  std::vector<uint32_t> first_of(welding.unique_count, UINT32_MAX);
  for (uint32_t v = 0; v < remap.size(); ++v) {
    if (first_of[remap[v]] == UINT32_MAX) first_of[remap[v]] = v;
    welding.canonical[v] = first_of[remap[v]];
  }
  return welding;
}

std::vector<std::string> connectivityWarnings(const Mesh& mesh, const Topology& topology) {
  if (mesh.faceCount() < 2) return {};
  for (const MeshEdge& edge : topology.edges) {
    if (edge.face_count >= 2) return {};
  }
  const Welding welding = weldByPosition(mesh);
  return {"no two of its " + std::to_string(mesh.faceCount()) +
          " faces share an edge (a polygon soup): every face is its own surface, so errors "
          "against the limit read 0 and say nothing" +
          (welding.unique_count < mesh.positions.size()
               ? "; " + std::to_string(mesh.positions.size() - welding.unique_count) +
                     " positions repeat others exactly: weld them (e.g. meshoptimizer's "
                     "generateVertexRemap) before measuring"
               : std::string())};
}

}  // namespace tb::mesh
