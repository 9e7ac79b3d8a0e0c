#include "techniques/phong/phong.h"

#include "harness/mesh/triangulate.h"
#include "techniques/phong/phong_eval.h"
#include "techniques/registry.h"
#include "harness/mesh/render_vertices.h"

namespace tb::phong {
namespace {

class PhongPatches final : public SurfacePatches {
 public:
  PhongPatches(Triangulation triangulation, double alpha)
      : tri_(std::move(triangulation)), alpha_(alpha) {
    if (tri_.polygons_split > 0) {
      warnings_.push_back(std::to_string(tri_.polygons_split) +
                          " polygons with more than 3 vertices were fan-triangulated");
    }
    if (tri_.mesh.normals_computed) {
      warnings_.push_back("the mesh has no normals: angle-weighted smooth normals were computed");
    }
  }

  PatchDomain domain() const override { return PatchDomain::kTriangle; }
  size_t patchCount() const override { return tri_.mesh.faceCount(); }
  const Mesh& controlMesh() const override { return tri_.mesh; }

  std::array<uint32_t, 4> patchCorners(size_t patch) const override {
    const auto face = tri_.mesh.facePositions(patch);
    return {face[0], face[1], face[2], UINT32_MAX};
  }

  uint32_t sourceFace(size_t patch) const override { return tri_.source_face[patch]; }

  SurfacePoint evaluate(size_t patch, const DomainCoord& coord) const override {
    const Mesh& mesh = tri_.mesh;
    const uint32_t first = mesh.face_offsets[patch];
    PhongTriangle<double> tri;
    for (int i = 0; i < 3; ++i) {
      tri.position[i] = mesh.positions[mesh.corner_positions[first + i]];
      tri.normal[i] = normalize(mesh.normals[mesh.corner_normals[first + i]]);
    }
    const PhongPoint<double> point = evaluatePhong(tri, {coord[0], coord[1], coord[2]}, alpha_);
    return {point.position, point.normal};
  }

  SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& coord) const override {
    const Mesh& mesh = tri_.mesh;
    const uint32_t first = mesh.face_offsets[patch];
    PhongTriangle<float> tri;
    for (int i = 0; i < 3; ++i) {
      tri.position[i] = vecCast<float>(mesh.positions[mesh.corner_positions[first + i]]);
      tri.normal[i] = normalize(vecCast<float>(mesh.normals[mesh.corner_normals[first + i]]));
    }
    const PhongPoint<float> point =
        evaluatePhong(tri, {coord[0], coord[1], coord[2]}, float(alpha_));
    return {point.position, point.normal};
  }

  DataFootprint footprint() const override {
    // Phong needs nothing beyond the vertex buffer and index buffer.
    return {triangleControlMeshBytes(tri_.mesh), 0, 0};
  }

  const std::vector<std::string>& warnings() const override { return warnings_; }

 private:
  Triangulation tri_;
  double alpha_;
  std::vector<std::string> warnings_;
};

}  // namespace

const TechniqueInfo& PhongTechnique::info() const {
  static const TechniqueInfo kInfo{
      "phong", TechniqueFamily::kSurface, "Phong tessellation",
      "Boubekeur & Alexa, Phong Tessellation, ACM TOG 27(5) (SIGGRAPH Asia 2008)",
      "triangle meshes with vertex normals; polygons are fan-triangulated; missing normals are "
      "computed"};
  return kInfo;
}

std::vector<VariantInfo> PhongTechnique::variants() const {
  // Default first: the paper's α = 3/4.
  return {
      {"alpha0.75", "shape factor 0.75 (the paper's choice)", {{"alpha", 0.75}}},
      {"alpha0", "shape factor 0: the flat triangle", {{"alpha", 0.0}}},
      {"alpha0.5", "shape factor 0.5", {{"alpha", 0.5}}},
      {"alpha1", "shape factor 1: full projection", {{"alpha", 1.0}}},
  };
}

std::string PhongTechnique::checkSupport(const Mesh& mesh) const {
  if (mesh.faceCount() == 0) return "phong: " + mesh.source + " has no faces";
  if (!mesh.hasNormals()) return "phong: " + mesh.source + " has no normals (load computes them)";
  return {};
}

std::unique_ptr<SurfacePatches> PhongTechnique::buildPatches(const Mesh& mesh,
                                                             const VariantInfo& variant) const {
  if (std::string reason = checkSupport(mesh); !reason.empty()) throw UnsupportedInput(reason);
  const auto alpha = variant.parameters.find("alpha");
  return std::make_unique<PhongPatches>(
      fanTriangulate(mesh), alpha == variant.parameters.end() ? kDefaultAlpha : alpha->second);
}

TB_REGISTER_TECHNIQUE(PhongTechnique);

}  // namespace tb::phong
