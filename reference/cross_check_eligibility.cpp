#include "reference/cross_check_eligibility.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "core/mesh/topology.h"
#include "reference/mesh_checks.h"

namespace tb::ref {
namespace {

// Embree's subdivision faces hold 3 to 15 corners.
constexpr uint32_t kEmbreeMaxFaceSize = 15;

bool isFractional(double sharpness) {
  return sharpness > 0 && sharpness < kInfiniteSharpness && sharpness != std::floor(sharpness);
}

// Sharp features meeting at one vertex: tagged creases (the last tag of an edge wins,
// as in Far), boundary edges (infinitely sharp under every boundary mode with a limit
// surface) and the vertex's corner sharpness.
struct VertexFeatures {
  std::vector<double> semi_sharp;  // finite crease sharpness > 0 of incident edges
  uint32_t sharp_edges = 0;        // semi-sharp + infinitely sharp creases + boundary edges
  double corner = 0;
};

std::vector<VertexFeatures> vertexFeatures(const mesh::Mesh& mesh, const mesh::Topology& topology) {
  std::vector<VertexFeatures> features(mesh.positions.size());
  const auto creases = creaseSharpnessByEdge(mesh);
  for (const mesh::MeshEdge& edge : topology.edges) {
    const auto tagged = creases.find({edge.v0, edge.v1});
    const double sharpness = edge.face_count == 1      ? kInfiniteSharpness
                             : tagged != creases.end() ? tagged->second
                                                       : 0.0;
    if (!(sharpness > 0)) continue;
    for (uint32_t v : {edge.v0, edge.v1}) {
      ++features[v].sharp_edges;
      if (sharpness < kInfiniteSharpness) features[v].semi_sharp.push_back(sharpness);
    }
  }
  for (const mesh::Corner& corner : mesh.tags.corners) {
    if (corner.vertex < features.size()) features[corner.vertex].corner = corner.sharpness;
  }
  return features;
}

// Why Sdc's and Embree's rules differ at this vertex, or "". Each case was measured
// on a 7x7 grid against Bfr: Embree is off by 1e-3 to 1e-2 of the diagonal where
//  - semi-sharp creases of unequal sharpness meet (Sdc blends the Crease -> Dart
//    transition differently);
//  - three or more sharp edges meet and one is fractional (the Corner transition);
//  - a fractional corner is less sharp than a crease or boundary edge at its vertex
//    (the Corner -> Crease transition; a corner at least as sharp as its creases agrees).
std::string vertexMismatch(const VertexFeatures& f) {
  const auto [lo, hi] = std::minmax_element(f.semi_sharp.begin(), f.semi_sharp.end());
  if (f.semi_sharp.size() >= 2 && *lo != *hi) return "semi-sharp creases of unequal sharpness";
  const bool fractional_edge = std::any_of(f.semi_sharp.begin(), f.semi_sharp.end(), isFractional);
  if (f.sharp_edges >= 3 && fractional_edge) {
    return "fractional crease sharpness where three or more sharp edges meet";
  }
  const double sharpest_edge = f.sharp_edges == f.semi_sharp.size()
                                   ? (f.semi_sharp.empty() ? 0.0 : *hi)
                                   : kInfiniteSharpness;
  if (isFractional(f.corner) && f.corner < sharpest_edge) {
    return "fractional corner sharpness below that of a crease or boundary edge";
  }
  return "";
}

}  // namespace

std::string crossCheckIneligibility(const mesh::Mesh& mesh, osd::Scheme scheme) {
  if (scheme == osd::Scheme::kLoop) return "Loop scheme: Embree subdivision is Catmull-Clark only";
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (mesh.faceSize(f) > kEmbreeMaxFaceSize) {
      return mesh::describeFace(mesh, f) + " has " + std::to_string(mesh.faceSize(f)) +
             " corners; Embree takes at most 15";
    }
  }
  if (!mesh.tags.holes.empty()) {
    return std::to_string(mesh.tags.holes.size()) + " hole face(s)";
  }
  if (mesh.tags.crease_method == "chaikin") return "Chaikin creases (`t creasemethod chaikin`)";
  // Embree stops refining sharp features after 10 levels and approximates the rest;
  // an infinitely sharp crease is then off by ~4e-5 of the diagonal, a corner by ~5e-4.
  for (const mesh::Crease& crease : mesh.tags.creases) {
    if (crease.sharpness >= kInfiniteSharpness) {
      return "infinitely sharp crease (sharpness >= 10) on edge " + std::to_string(crease.v0) +
             "-" + std::to_string(crease.v1);
    }
  }
  for (const mesh::Corner& corner : mesh.tags.corners) {
    if (corner.sharpness >= kInfiniteSharpness) {
      return "infinitely sharp corner (sharpness >= 10) at vertex " + std::to_string(corner.vertex);
    }
  }

  const mesh::Topology topology = mesh::buildTopology(mesh);
  if (const size_t count = topology.nonManifoldEdgeCount(); count > 0) {
    return std::to_string(count) + " non-manifold edge(s)";
  }
  for (size_t v = 0; v < topology.valence.size(); ++v) {
    if (topology.valence[v] == 2 && !topology.on_boundary[v]) {
      return "interior valence-2 vertex " + std::to_string(v);
    }
    // Sdc's edge-only rule and Embree's SMOOTH_BOUNDARY agree on the boundary curve
    // but not inside the faces at a valence-2 corner (2e-3 of the diagonal measured
    // on catmark_edgecorner); boundaries without such corners agree.
    if (topology.valence[v] == 2 && mesh.tags.boundary == mesh::BoundaryInterpolation::kEdgeOnly) {
      return "edge-only boundary interpolation at valence-2 corner " + std::to_string(v);
    }
  }
  const std::vector<VertexFeatures> features = vertexFeatures(mesh, topology);
  for (size_t v = 0; v < features.size(); ++v) {
    if (const std::string why = vertexMismatch(features[v]); !why.empty()) {
      return why + " at vertex " + std::to_string(v);
    }
  }
  return "";
}

}  // namespace tb::ref
