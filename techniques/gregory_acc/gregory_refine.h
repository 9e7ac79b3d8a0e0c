// One uniform Catmull-Clark refinement of a manifold polygon mesh, as stencils
// over the input vertices. gregory_acc's `quads_only` variant uses it for meshes with
// non-quad faces: every face of the refined mesh is a quad, and the refined mesh has the
// same limit surface (OpenSubdiv isolates non-quads the same way), so quad Gregory patches
// alone cover it. The default variant keeps triangle faces as triangle Gregory patches
// instead (SurfacePatches::patchDomain per patch).
#pragma once

#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "core/mesh/mesh.h"

namespace tb::gregory_acc {

using Stencil = std::map<uint32_t, double>;  // input vertex index -> weight, ascending

struct RefinedMesh {
  // Positions: the input's vertex points first (same indices), then one edge point per
  // edge, then one face point per face. Face k of face f of the input is the quad
  // (vertex point k, edge point (k, k+1), face point, edge point (k-1, k)).
  mesh::Mesh mesh;
  std::vector<Stencil> stencils;      // per refined position, over input positions
  std::vector<uint32_t> source_face;  // input face of each refined face
  // Refined position of the edge point of input edge (a, b), either direction.
  uint32_t edgePoint(uint32_t a, uint32_t b) const {
    return edge_point.at(a < b ? (uint64_t(a) << 32) | b : (uint64_t(b) << 32) | a);
  }
  std::unordered_map<uint64_t, uint32_t> edge_point;  // edgePoint's table
};

// Boundary edges are infinitely sharp and one-face boundary vertices are corners
// (Sdc EDGE_AND_CORNER). Precondition: checkGregorySupport(mesh) is empty.
RefinedMesh refineOnce(const mesh::Mesh& mesh);

}  // namespace tb::gregory_acc
