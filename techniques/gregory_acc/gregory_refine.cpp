#include "techniques/gregory_acc/gregory_refine.h"

#include <array>
#include <unordered_map>

#include "techniques/gregory_acc/gregory_rings.h"  // add: stencil arithmetic

namespace tb::gregory_acc {
namespace {

uint64_t edgeKey(uint32_t a, uint32_t b) {
  return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a;
}

}  // namespace

RefinedMesh refineOnce(const mesh::Mesh& mesh) {
  const uint32_t vertex_count = uint32_t(mesh.positions.size());
  RefinedMesh out;
  out.mesh.source = mesh.source;
  out.mesh.tags = mesh.tags;

  // Face points: centroids.
  std::vector<Stencil> face_point(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    for (uint32_t v : fv) face_point[f][v] += 1.0 / double(fv.size());
  }
  // Edge points (a + b + F_left + F_right) / 4; closed manifold: two faces per edge.
  std::unordered_map<uint64_t, uint32_t> edge_index;
  std::vector<Stencil> edge_point;
  std::vector<std::array<uint32_t, 2>> edge_ends;
  std::vector<uint32_t> edge_faces;
  std::vector<std::vector<uint32_t>> vertex_faces(vertex_count);
  std::vector<std::vector<uint32_t>> vertex_neighbours(vertex_count);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    for (size_t k = 0; k < fv.size(); ++k) {
      const uint32_t a = fv[k], b = fv[(k + 1) % fv.size()];
      vertex_faces[a].push_back(uint32_t(f));
      const auto [it, inserted] = edge_index.emplace(edgeKey(a, b), uint32_t(edge_point.size()));
      if (inserted) {
        edge_ends.push_back({a, b});
        edge_faces.push_back(0);
        edge_point.emplace_back();
        edge_point.back()[a] += 0.25;
        edge_point.back()[b] += 0.25;
        vertex_neighbours[a].push_back(b);
        vertex_neighbours[b].push_back(a);
      }
      add(edge_point[it->second], face_point[f], 0.25);
      ++edge_faces[it->second];
    }
  }
  // Boundary edges (EDGE_AND_CORNER: infinitely sharp): the midpoint.
  std::vector<std::vector<uint32_t>> boundary_neighbours(vertex_count);
  for (size_t e = 0; e < edge_point.size(); ++e) {
    if (edge_faces[e] != 1) continue;
    const auto [a, b] = edge_ends[e];
    edge_point[e] = Stencil{{a, 0.5}, {b, 0.5}};
    boundary_neighbours[a].push_back(b);
    boundary_neighbours[b].push_back(a);
  }
  // Vertex points (Q + 2R + (n - 3) v) / n: Q the mean face point, R the mean edge
  // midpoint, n the valence.
  out.stencils.resize(vertex_count);
  for (uint32_t v = 0; v < vertex_count; ++v) {
    const double n = double(vertex_faces[v].size());
    Stencil& s = out.stencils[v];
    if (n == 0 || (boundary_neighbours[v].size() == 2 && n == 1)) {
      s[v] = 1;  // unused position (kept so indices stay aligned), or a boundary corner
      continue;
    }
    if (boundary_neighbours[v].size() == 2) {  // smooth boundary: the crease rule
      s[v] += 6.0 / 8;
      s[boundary_neighbours[v][0]] += 1.0 / 8;
      s[boundary_neighbours[v][1]] += 1.0 / 8;
      continue;
    }
    s[v] += (n - 3) / n;
    for (uint32_t f : vertex_faces[v]) add(s, face_point[f], 1.0 / (n * n));
    for (uint32_t w : vertex_neighbours[v]) {
      s[v] += 1.0 / (n * n);
      s[w] += 1.0 / (n * n);
    }
  }
  const uint32_t first_edge = vertex_count;
  const uint32_t first_face = first_edge + uint32_t(edge_point.size());
  out.stencils.insert(out.stencils.end(), edge_point.begin(), edge_point.end());
  out.stencils.insert(out.stencils.end(), face_point.begin(), face_point.end());
  for (const Stencil& s : out.stencils) {
    mesh::Vec3d p{};
    for (const auto& [index, weight] : s) p = p + mesh.positions[index] * weight;
    out.mesh.positions.push_back(p);
  }
  for (const auto& [key, index] : edge_index) out.edge_point.emplace(key, first_edge + index);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    const size_t size = fv.size();
    for (size_t k = 0; k < size; ++k) {
      const uint32_t prev = fv[(k + size - 1) % size], here = fv[k], next = fv[(k + 1) % size];
      const std::array<uint32_t, 4> quad = {here, first_edge + edge_index.at(edgeKey(here, next)),
                                            first_face + uint32_t(f),
                                            first_edge + edge_index.at(edgeKey(prev, here))};
      out.mesh.addFace(quad, {}, {}, 0);
      out.source_face.push_back(uint32_t(f));
    }
  }
  return out;
}

}  // namespace tb::gregory_acc
