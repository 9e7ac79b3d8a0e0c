// Creases, corners, holes and boundary interpolation for the ACC-family patches (acc,
// gregory_acc), after Kovacs, Mitchell, Drone & Zorin, "Real-Time Creased Approximate
// Subdivision Surfaces" (I3D 2009): an infinitely sharp edge is a boundary to each side, so
// both sides build the limit's crease curve; finite sharpness is refined away uniformly with
// OpenSubdiv within a face budget (the leftover rounded); holes get no patch. The vertex
// kinds and every rule: docs/derivations/creases.md. The refined mesh keeps its true tags, so
// a reference built over it is the input's own limit.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::techniques {

enum class SharpVertexKind : uint8_t {
  kSmooth,  // no sharp edge
  kDart,    // one sharp edge: smooth rules, whole ring
  kCrease,  // two sharp edges: the crease curve's B-spline rules, one ring per sector
  kCorner,  // interpolated: three or more sharp edges, or a sharp vertex tag on a crease
  kCone,    // an infinitely sharp vertex tag with fewer than two sharp edges: no patch
            // construction here represents it (the technique refuses it)
};

struct CreasePreparation {
  // Faces [0, patch_faces) carry patches, in input order; the faces after them have no
  // limit surface (holes). Positions: the input's, or the refined level's.
  mesh::Mesh control;
  size_t patch_faces = 0;
  std::vector<uint32_t> source_face;  // per control face: the input face it refines
  int levels = 0;                     // refinement steps applied
  int levels_needed = 0;              // steps for every finite sharpness to decay to 0
  double rounded_sharpness = 0;       // largest finite sharpness left over (rounded)
  // Infinitely sharp edges of `control` as the patches honour them, boundary edges
  // included under edge-only and edge-and-corner interpolation: sharpEdgeKey(a, b).
  std::unordered_set<uint64_t> sharp_edges;
  std::vector<SharpVertexKind> vertex_kind;  // per control position
  std::vector<std::string> notes;            // for the instance's warnings

  bool isSharp(uint32_t a, uint32_t b) const { return sharp_edges.count(sharpEdgeKey(a, b)) != 0; }
  static uint64_t sharpEdgeKey(uint32_t a, uint32_t b) {
    return a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a;
  }
};

// Refines `mesh` while finite sharpness remains and the refined mesh has at most
// `max_faces` faces (a mesh without finite sharpness is not refined). Throws
// UnsupportedInput "<technique>: ..." when OpenSubdiv refuses the mesh's topology or tags.
// `min_levels` steps are applied whatever the budget (gregory_acc: 1 for a mesh whose
// non-quad faces it cannot patch next to sharp features; acc passes none).
CreasePreparation prepareCreases(const mesh::Mesh& mesh, const std::string& technique,
                                 size_t max_faces, int min_levels = 0);

// The default face budget of refinement for creases: acc and gregory_acc refine at most
// until the control mesh has this many faces (a variant parameter may raise it).
inline constexpr size_t kDefaultCreaseFaceBudget = 256;

}  // namespace tb::techniques
