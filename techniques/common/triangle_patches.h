// What every triangle technique's patches share: patch p is triangle p of the
// fan-triangulated input, corners in the triangle's order, warnings about the
// triangulation and computed normals. A technique derives and adds its evaluation.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/triangulate.h"
#include "techniques/technique.h"

namespace tb::techniques {

class TrianglePatchesBase : public SurfacePatches {
 public:
  explicit TrianglePatchesBase(mesh::Triangulation triangulation)
      : tri_(std::move(triangulation)), warnings_(mesh::triangulationWarnings(tri_)) {}

  PatchDomain patchDomain(size_t) const override { return PatchDomain::kTriangle; }
  size_t patchCount() const override { return tri_.mesh.faceCount(); }
  const mesh::Mesh& controlMesh() const override { return tri_.mesh; }
  std::array<uint32_t, 4> patchCorners(size_t patch) const override {
    const auto face = tri_.mesh.facePositions(patch);
    return {face[0], face[1], face[2], UINT32_MAX};
  }
  uint32_t sourceFace(size_t patch) const override { return tri_.source_face[patch]; }
  const std::vector<std::string>& warnings() const override { return warnings_; }

 protected:
  mesh::Triangulation tri_;
  std::vector<std::string> warnings_;
};

}  // namespace tb::techniques
