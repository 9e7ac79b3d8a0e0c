#include "techniques/gregory_acc/gregory_acc.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <utility>

#include "shaders/gregory_acc/gregory_layout.h"
#include "techniques/gregory_acc/gregory_batch.h"
#include "techniques/gregory_acc/gregory_bounds.h"
#include "techniques/gregory_acc/gregory_eval.h"
#include "techniques/gregory_acc/gregory_stencils.h"
#include "techniques/registry.h"
#include "techniques/variant_param.h"

namespace tb::gregory_acc {
namespace {

// The quad patch's position (the screen-space error's point-by-point evaluation) built for
// AVX2 where the processor has it: the same operations in the same order (fp-contract=off, so
// nothing fuses), the same point bit for bit (tests/techniques/batch_eval_test.cpp compares it
// with evaluate(), built for generic x86-64); about 13 % off full-suite adaptivity.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
[[gnu::target("avx2"), gnu::flatten, gnu::optimize("fp-contract=off")]] mesh::Vec3d
quadPositionAvx2(const GregoryPoints<double>& cp, double u, double v, bool symmetric_edges) {
  return evaluateGregoryPosition(cp, u, v, symmetric_edges);
}
mesh::Vec3d quadPositionFast(const GregoryPoints<double>& cp, double u, double v,
                             bool symmetric_edges) {
  static const bool has_avx2 = __builtin_cpu_supports("avx2");
  return has_avx2 ? quadPositionAvx2(cp, u, v, symmetric_edges)
                  : evaluateGregoryPosition(cp, u, v, symmetric_edges);
}
#else
mesh::Vec3d quadPositionFast(const GregoryPoints<double>& cp, double u, double v,
                             bool symmetric_edges) {
  return evaluateGregoryPosition(cp, u, v, symmetric_edges);
}
#endif

constexpr uint64_t kGpuVertexBytes = 16;     // vec4 position (std430)
constexpr uint64_t kStencilEntryBytes = 8;   // uvec2 (vertex index, float weight bits)
constexpr uint64_t kStencilOffsetBytes = 4;  // uint per stencil + 1
constexpr uint64_t kPatchPointIdBytes = 4;   // uint stencil id per control point

class GregoryPatches final : public techniques::SurfacePatches {
 public:
  GregoryPatches(const mesh::Mesh& mesh, bool symmetric_edges, TangentMask mask,
                 NonQuadFaces non_quads, size_t crease_face_budget)
      : build_(buildGregory(mesh, mask, non_quads, crease_face_budget)),
        positions_(build_.creases.control.positions),
        stencils_(build_.stencils),
        symmetric_edges_(symmetric_edges) {
    warnings_ = build_.creases.notes;
    if (build_.refined) {
      warnings_.push_back(std::string(non_quads == NonQuadFaces::kRefineOnce
                                          ? "non-quad faces"
                                          : "faces of 5 or more vertices") +
                          ": the mesh was refined once (Catmull-Clark) and " +
                          std::to_string(build_.control.faceCount()) +
                          " quad Gregory patches built on the refined mesh");
    }
    for (size_t p = 0; p < patchCount(); ++p) {
      (patchDomain(p) == techniques::PatchDomain::kQuad ? quad_patches_ : triangle_patches_)
          .push_back(uint32_t(p));
    }
    positions_f_.reserve(positions_.size());
    for (const mesh::Vec3d& p : positions_) positions_f_.push_back(vecCast<float>(p));
    weights_f_.reserve(stencils_.weights.size());
    for (double w : stencils_.weights) weights_f_.push_back(float(w));
    // The control points of every patch, once (what the TCS computes per draw).
    points_d_.reserve(patchCount());
    points_f_.reserve(patchCount());
    for (size_t p = 0; p < patchCount(); ++p) {
      points_d_.push_back(controlPoints<double>(
          p, [this](uint32_t i) { return positions_[i]; },
          [this](uint32_t k) { return stencils_.weights[k]; }));
      points_f_.push_back(controlPoints<float>(
          p, [this](uint32_t i) { return positions_f_[i]; },
          [this](uint32_t k) { return weights_f_[k]; }));
    }
  }

  // Quads, and (unless the mesh was refined) triangles: patch p is face p; the faces
  // after patchCount() are holes.
  techniques::PatchDomain patchDomain(size_t patch) const override {
    return build_.control.faceSize(patch) == 3 ? techniques::PatchDomain::kTriangle
                                               : techniques::PatchDomain::kQuad;
  }
  techniques::LimitScheme approximates() const override {
    return techniques::LimitScheme::kCatmullClark;
  }
  size_t patchCount() const override { return build_.patch_count; }
  const mesh::Mesh& controlMesh() const override { return build_.control; }

  std::array<uint32_t, 4> patchCorners(size_t patch) const override {
    const auto face = build_.control.facePositions(patch);
    return {face[0], face[1], face[2], face.size() == 4 ? face[3] : UINT32_MAX};
  }

  uint32_t sourceFace(size_t patch) const override { return build_.source_face[patch]; }

  techniques::SurfacePoint evaluate(size_t patch,
                                    const techniques::DomainCoord& coord) const override {
    assert(patch < patchCount());
    const GregoryPoint<double> point = evaluatePatch(points_d_[patch], patch, coord);
    return {point.position, point.normal};
  }

  mesh::Vec3d evaluatePosition(size_t patch, const techniques::DomainCoord& coord) const override {
    assert(patch < patchCount());
    const GregoryPoints<double>& cp = points_d_[patch];
    if (patchDomain(patch) == techniques::PatchDomain::kTriangle) {
      return evaluateGregoryTrianglePosition(cp, coord[0], coord[1], coord[2], symmetric_edges_);
    }
    return quadPositionFast(cp, coord[0], coord[1], symmetric_edges_);
  }

  std::unique_ptr<techniques::BatchPattern> makeBatchPattern(
      techniques::PatchDomain domain, std::vector<techniques::DomainCoord> coords,
      techniques::BatchOutput output) const override {
    return std::make_unique<GregoryBatchPattern>(domain, std::move(coords), output,
                                                 symmetric_edges_);
  }

  // Patterns made by another gregory_acc surface are used as they are when their edge
  // rule is this one's; anything else goes point by point.
  void evaluateBatch(size_t patch, const techniques::BatchPattern& pattern,
                     techniques::BatchPoints& out) const override {
    assert(patch < patchCount());
    const auto* gregory = dynamic_cast<const GregoryBatchPattern*>(&pattern);
    if (gregory == nullptr || gregory->symmetricEdges() != symmetric_edges_ ||
        gregory->domain() != patchDomain(patch)) {
      return evaluateBatchPointByPoint(patch, pattern, out);
    }
    gregory->evaluate(points_d_[patch], out);
  }

  techniques::SurfacePointF evaluateFloat(size_t patch,
                                          const tess::DomainPoint& coord) const override {
    assert(patch < patchCount());
    const GregoryPoint<float> point = evaluatePatch(points_f_[patch], patch, coord);
    return {point.position, point.normal};
  }

  // gregory_bounds.h: the control points, and the cone of the rational patch's normals.
  std::optional<techniques::PatchCullBounds> cullBounds(size_t patch) const override {
    return patchDomain(patch) == techniques::PatchDomain::kTriangle
               ? gregoryTriangleCullBounds(points_d_[patch])
               : gregoryQuadCullBounds(points_d_[patch]);
  }

  // gregory_bounds.h: the midpoint net's bounds plus the rational blends' share.
  std::optional<techniques::CurvatureBounds> curvatureBounds(size_t patch) const override {
    return patchDomain(patch) == techniques::PatchDomain::kTriangle
               ? gregoryTriangleCurvatureBounds(points_d_[patch])
               : gregoryQuadCurvatureBounds(points_d_[patch]);
  }

  // One program per domain present: the quads' (20 control points per patch) and the
  // triangles' (15); each reads the same vertex and stencil buffers. A single-domain
  // mesh gets one program whose patch p is patch p.
  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override {
    std::vector<gpu::GpuPatchProgram> programs;
    for (const std::vector<uint32_t>* ids : {&quad_patches_, &triangle_patches_}) {
      if (ids->empty()) continue;
      const bool quads = ids == &quad_patches_;
      gpu::GpuPatchProgram program = sharedBuffersProgram();
      program.control_shader =
          quads ? "gregory_acc/gregory_acc.tesc" : "gregory_acc/gregory_tri.tesc";
      program.evaluation_shader =
          quads ? "gregory_acc/gregory_acc.tese" : "gregory_acc/gregory_tri.tese";
      program.compute_shader =
          quads ? "gregory_acc/gregory_acc.comp" : "gregory_acc/gregory_tri.comp";
      program.domain = quads ? tess::Domain::kQuad : tess::Domain::kTriangle;
      program.patch_count = uint32_t(ids->size());
      if (ids->size() != patchCount()) program.patch_ids = *ids;
      const uint32_t points = quads ? kPointsPerPatch : kPointsPerTriangle;
      std::vector<uint32_t> patch_points;
      for (uint32_t p : *ids) {
        const auto& ids_of_patch = stencils_.patch_points[p];
        patch_points.insert(patch_points.end(), ids_of_patch.begin(),
                            ids_of_patch.begin() + points);
      }
      gpu::setStorageBuffer(program, TB_GREGORY_BINDING_PATCH_POINTS, std::move(patch_points));
      programs.push_back(std::move(program));
    }
    return programs;
  }

 private:
  // Buffers 1..3 of both programs: vertices, stencil offsets, stencil entries; the
  // per-patch stencil ids (buffer 4) are added per program.
  gpu::GpuPatchProgram sharedBuffersProgram() const {
    gpu::GpuPatchProgram program;
    std::vector<uint32_t> vertices;
    for (const mesh::Vec3f& p : positions_f_) {
      for (float x : {p.x, p.y, p.z, 1.0f}) vertices.push_back(std::bit_cast<uint32_t>(x));
    }
    std::vector<uint32_t> entries;
    for (size_t k = 0; k < stencils_.indices.size(); ++k) {
      entries.push_back(stencils_.indices[k]);
      entries.push_back(std::bit_cast<uint32_t>(weights_f_[k]));
    }
    gpu::setStorageBuffer(program, TB_GREGORY_BINDING_VERTICES, std::move(vertices));
    gpu::setStorageBuffer(program, TB_GREGORY_BINDING_STENCIL_OFFSETS, stencils_.offsets);
    gpu::setStorageBuffer(program, TB_GREGORY_BINDING_STENCIL_ENTRIES, std::move(entries));
    program.specialization = {symmetric_edges_ ? 1u : 0u};
    return program;
  }

  template <class T>
  GregoryPoint<T> evaluatePatch(const GregoryPoints<T>& cp, size_t patch, const auto& coord) const {
    if (patchDomain(patch) == techniques::PatchDomain::kTriangle) {
      return evaluateGregoryTriangle(cp, T(coord[0]), T(coord[1]), T(coord[2]), symmetric_edges_);
    }
    return evaluateGregory(cp, T(coord[0]), T(coord[1]), symmetric_edges_);
  }

 public:
  std::optional<techniques::OperationProfile> operationProfile(size_t patch) const override {
    using C = techniques::CountingScalar<float>;
    techniques::OperationProfile profile;
    techniques::resetOperationCounts();
    const GregoryPoints<C> cp = controlPoints<C>(
        patch,
        [this](uint32_t i) {
          const mesh::Vec3f& p = positions_f_[i];
          return mesh::Vec3T<C>{p.x, p.y, p.z};
        },
        [this](uint32_t k) { return C(weights_f_[k]); });
    profile.per_patch_setup = techniques::operationCounts();
    techniques::resetOperationCounts();
    const bool triangle = patchDomain(patch) == techniques::PatchDomain::kTriangle;
    if (triangle) {
      evaluateGregoryTriangle(cp, C(0.25f), C(0.375f), C(0.375f), symmetric_edges_);
    } else {
      evaluateGregory(cp, C(0.3f), C(0.6f), symmetric_edges_);
    }
    profile.per_vertex = techniques::operationCounts();
    techniques::resetOperationCounts();
    profile.note = std::string(triangle ? "15 stencil sums per triangle patch (TCS); "
                                        : "20 stencil sums per quad patch (TCS); ") +
                   "interior point, " + (symmetric_edges_ ? "edge_symmetric" : "asymmetric") +
                   " order, position + analytic normal (TES)";
    return profile;
  }

  techniques::DataFootprint footprint() const override {
    techniques::DataFootprint footprint;
    footprint.control_mesh_bytes = positions_.size() * kGpuVertexBytes;
    footprint.patch_data_bytes =
        (quad_patches_.size() * kPointsPerPatch + triangle_patches_.size() * kPointsPerTriangle) *
        kPatchPointIdBytes;
    footprint.stencil_bytes = stencils_.offsets.size() * kStencilOffsetBytes +
                              stencils_.indices.size() * kStencilEntryBytes;
    return footprint;
  }

  const std::vector<std::string>& warnings() const override { return warnings_; }

 private:
  template <class T, class PositionAt, class WeightAt>
  GregoryPoints<T> controlPoints(size_t patch, const PositionAt& position,
                                 const WeightAt& weight) const {
    GregoryPoints<T> cp{};
    const uint32_t points =
        patchDomain(patch) == techniques::PatchDomain::kQuad ? kPointsPerPatch : kPointsPerTriangle;
    for (uint32_t i = 0; i < points; ++i) {
      cp[i] = stencilPoint<T>(stencils_, stencils_.patch_points[patch][i], position, weight);
    }
    return cp;
  }

  GregoryBuild build_;
  std::vector<mesh::Vec3d> positions_;  // build_.creases.control's, which every stencil reads
  const GregoryStencils& stencils_;
  bool symmetric_edges_;
  std::vector<mesh::Vec3f> positions_f_;
  std::vector<float> weights_f_;
  std::vector<GregoryPoints<double>> points_d_;
  std::vector<GregoryPoints<float>> points_f_;
  std::vector<uint32_t> quad_patches_, triangle_patches_;  // patch ids by domain
  std::vector<std::string> warnings_;
};

}  // namespace

const techniques::TechniqueInfo& GregoryAccTechnique::info() const {
  static const techniques::TechniqueInfo kInfo{
      "gregory_acc", techniques::TechniqueFamily::kSurface,
      "Gregory ACC (quad and triangle Gregory patches)",
      "Loop, Schaefer, Ni & Castaño, Approximating Subdivision Surfaces with Gregory Patches "
      "for Hardware Tessellation, ACM TOG 28(5) (SIGGRAPH Asia 2009)",
      "manifold Catmull-Clark meshes, valence 3..256, face size 3..32; creases, corners, holes "
      "and every boundary interpolation (semi-sharp creases refined with OpenSubdiv until they "
      "decay, within a face budget; sharp edges bound the patches, Kovacs et al. 2009); no cone "
      "points (a sharp vertex tag off a crease) or smoothtriangles; quads and triangles get "
      "patches of their own, meshes with faces of 5+ vertices are refined once"};
  return kInfo;
}

std::vector<techniques::VariantInfo> GregoryAccTechnique::variants() const {
  return {
      {"edge_symmetric",
       "tensor-product Bernstein inside; domain-boundary points from the shared edge curve "
       "evaluated symmetrically (watertight in float)",
       {{"symmetric_edges", 1.0}}},
      // The default's patches in another float order (VariantInfo::evaluation_order_only).
      {"asymmetric",
       "tensor-product Bernstein everywhere (shared edges may differ in float)",
       {{"symmetric_edges", 0.0}},
       true,
       false,
       "shared edges evaluated by each patch's own tensor product crack in float"},
      {"exact_tangents",
       "edge_symmetric, edge points from the exact Catmull-Clark limit tangent masks "
       "(Halstead et al. 1993) instead of the paper's averaged face points",
       {{"symmetric_edges", 1.0}, {"exact_tangents", 1.0}}},
      // --suite full only: refining triangle-heavy meshes (tri_pawn: 3 quads per triangle)
      // cost a sixth of the default suite's time budget.
      {"quads_only",
       "edge_symmetric, but any non-quad face makes the whole mesh refined once (Catmull-Clark) "
       "and patched with quads: no triangle patches, 3 or 4 quads per input face",
       {{"symmetric_edges", 1.0}, {"quads_only", 1.0}},
       false,
       true},
  };
}

std::string GregoryAccTechnique::checkSupport(const mesh::Mesh& mesh) const {
  return checkGregorySupport(mesh);
}

std::unique_ptr<techniques::TechniqueInstance> GregoryAccTechnique::build(
    const techniques::TechniqueInput& input, const techniques::VariantInfo& variant) const {
  const mesh::Mesh& mesh = techniques::requireMesh(info(), input);
  const bool symmetric_edges = techniques::paramOr<bool>(info(), variant, "symmetric_edges", true);
  const TangentMask mask = techniques::paramOr<bool>(info(), variant, "exact_tangents", false)
                               ? TangentMask::kExactLimit
                               : TangentMask::kPaper;
  const NonQuadFaces non_quads = techniques::paramOr<bool>(info(), variant, "quads_only", false)
                                     ? NonQuadFaces::kRefineOnce
                                     : NonQuadFaces::kTrianglePatches;
  return std::make_unique<techniques::SurfaceInstance>(std::make_unique<GregoryPatches>(
      mesh, symmetric_edges, mask, non_quads, variantCreaseFaceBudget(variant)));
}

size_t variantCreaseFaceBudget(const techniques::VariantInfo& variant) {
  return size_t(std::max(
      1.0, techniques::paramOr<double>(GregoryAccTechnique().info(), variant, "crease_face_budget",
                                       double(techniques::kDefaultCreaseFaceBudget))));
}

TB_REGISTER_TECHNIQUE(GregoryAccTechnique);

}  // namespace tb::gregory_acc
