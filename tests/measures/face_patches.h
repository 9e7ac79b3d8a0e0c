// Base of the measures' test doubles: patch p is face p of a mesh, in the face's own
// domain (quad faces quads, triangles triangles), with no data footprint and no warnings.
// Subclasses give the surface (evaluate, evaluateFloat) and anything else they test.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/mesh.h"
#include "techniques/technique.h"

namespace tb::testing {

class FacePatches : public techniques::SurfacePatches {
 public:
  explicit FacePatches(mesh::Mesh mesh) : mesh_(std::move(mesh)) {}
  techniques::PatchDomain patchDomain(size_t patch) const override {
    return mesh_.faceSize(patch) == 4 ? techniques::PatchDomain::kQuad
                                      : techniques::PatchDomain::kTriangle;
  }
  size_t patchCount() const override { return mesh_.faceCount(); }
  const mesh::Mesh& controlMesh() const override { return mesh_; }
  std::array<uint32_t, 4> patchCorners(size_t patch) const override {
    std::array<uint32_t, 4> corners{UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX};
    const auto face = mesh_.facePositions(patch);
    std::copy(face.begin(), face.end(), corners.begin());
    return corners;
  }
  uint32_t sourceFace(size_t patch) const override { return uint32_t(patch); }
  techniques::DataFootprint footprint() const override { return {}; }
  const std::vector<std::string>& warnings() const override { return warnings_; }

 protected:
  // Corner k of patch p in float, as the test shaders read it.
  mesh::Vec3f cornerF(size_t patch, uint32_t k) const {
    return vecCast<float>(mesh_.positions[mesh_.facePositions(patch)[k]]);
  }
  mesh::Mesh mesh_;

 private:
  std::vector<std::string> warnings_;
};

}  // namespace tb::testing
