// Helpers shared by the gregory_acc test files: the bundled assets the technique accepts,
// the twin of every directed patch edge (for shared-edge checks), and the mesh whose limit
// the patches approximate (creases as the patches honour them).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/gregory_acc/gregory_acc.h"
#include "techniques/technique.h"
#include "tests/test_support.h"

namespace tb::gregory_acc::testing {

// Every bundled OBJ ("opensubdiv/catmark_cube.obj", ...) that checkSupport accepts, sorted;
// but the character's cage (full_suite/character_base.obj, the source of a production asset):
// 1,536 quads that the GPU test over every asset would pay for on lavapipe, with no case the
// others lack (extraordinary vertices of valence 3 and 6).
inline std::vector<std::string> supportedBundledAssets() {
  std::vector<std::string> names;
  GregoryAccTechnique technique;
  for (const char* folder : {"full_suite", "opensubdiv", "tessbench"}) {
    for (const auto& entry : std::filesystem::directory_iterator(tb::testing::assetPath(folder))) {
      if (entry.path().extension() != ".obj" || entry.path().stem() == "character_base") continue;
      const std::string name = std::string(folder) + "/" + entry.path().filename().string();
      if (technique.checkSupport(mesh::loadObjFile(tb::testing::assetPath(name))).empty()) {
        names.push_back(name);
      }
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct EdgeTwin {
  int64_t face = -1;  // -1: boundary edge
  int corner = 0;     // the twin is (corner, corner + 1) of `face`, running the other way
};

// twins[f * 4 + c]: the patch edge sharing edge (c, c + 1) of patch f (a quad or a
// triangle: patch f is face f of the control mesh).
inline std::vector<EdgeTwin> edgeTwins(const mesh::Mesh& mesh) {
  std::unordered_map<uint64_t, EdgeTwin> by_directed;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    for (size_t c = 0; c < fv.size(); ++c) {
      by_directed[(uint64_t(fv[c]) << 32) | fv[(c + 1) % fv.size()]] = {int64_t(f), int(c)};
    }
  }
  std::vector<EdgeTwin> twins(4 * mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const auto fv = mesh.facePositions(f);
    for (size_t c = 0; c < fv.size(); ++c) {
      const auto it = by_directed.find((uint64_t(fv[(c + 1) % fv.size()]) << 32) | fv[c]);
      if (it != by_directed.end()) twins[f * 4 + c] = it->second;
    }
  }
  return twins;
}

inline int cornerCount(techniques::PatchDomain domain) {
  return domain == techniques::PatchDomain::kQuad ? 4 : 3;
}

// The domain point of patch edge (corner, corner + 1) at parameter t from `corner`:
// quads (u, v, 0) with corners (0,0), (1,0), (1,1), (0,1); triangles barycentric.
template <class T>
std::array<T, 3> edgeCoord(techniques::PatchDomain domain, int corner, T t) {
  if (domain == techniques::PatchDomain::kTriangle) {
    std::array<T, 3> p{T(0), T(0), T(0)};
    p[corner] = T(1) - t;
    p[(corner + 1) % 3] = t;
    return p;
  }
  switch (corner) {
    case 0:
      return {t, T(0), T(0)};
    case 1:
      return {T(1), t, T(0)};
    case 2:
      return {T(1) - t, T(1), T(0)};
    default:
      return {T(0), T(1) - t, T(0)};
  }
}

// The crease preparation gregory_acc builds on for `input` with the default face budget
// (the same call gregory_acc makes for a mesh it does not refine for non-quads).
inline techniques::CreasePreparation defaultCreases(const mesh::Mesh& input) {
  return techniques::prepareCreases(input, "gregory_acc", techniques::kDefaultCreaseFaceBudget);
}

// The mesh whose limit surface the patches approximate: the patches' control mesh with
// its true remaining tags when the crease preparation rounded nothing (then its limit is
// the input's), else with the tags the patches honour: every sharp edge and every corner
// infinitely sharp, leftover finite sharpness gone.
inline mesh::Mesh limitMeshOf(const techniques::SurfacePatches& patches,
                              const techniques::CreasePreparation& creases) {
  const mesh::Mesh& control = patches.controlMesh();
  if (creases.rounded_sharpness == 0) return control;
  mesh::Mesh mesh = control;
  mesh.tags.creases.clear();
  mesh.tags.corners.clear();
  for (uint64_t key : creases.sharp_edges) {
    mesh.tags.creases.push_back({uint32_t(key >> 32), uint32_t(key & 0xffffffffu), 10.0});
  }
  for (size_t v = 0; v < creases.vertex_kind.size(); ++v) {
    if (creases.vertex_kind[v] == techniques::SharpVertexKind::kCorner)
      mesh.tags.corners.push_back({uint32_t(v), 10.0});
  }
  return mesh;
}

}  // namespace tb::gregory_acc::testing
