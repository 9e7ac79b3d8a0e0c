#include "techniques/pn_triangles/pn_triangles.h"

#include <cassert>

#include "core/mesh/render_vertices.h"
#include "core/mesh/triangulate.h"
#include "techniques/common/curvature_bounds.h"
#include "techniques/common/triangle_patches.h"
#include "techniques/pn_triangles/pn_bounds.h"
#include "techniques/pn_triangles/pn_build.h"
#include "techniques/pn_triangles/pn_eval.h"
#include "techniques/registry.h"
#include "techniques/variant_param.h"

namespace tb::pn_triangles {
namespace {

class PnPatches final : public techniques::TrianglePatchesBase {
 public:
  PnPatches(mesh::Triangulation triangulation, const techniques::TriangleRecordOptions& options)
      : techniques::TrianglePatchesBase(std::move(triangulation)),
        options_(options),
        build_(techniques::buildTriangleRecords(tri_.mesh, options_)) {
    // The double and float control nets, once per patch (what every evaluate() and
    // evaluateFloat() would recompute).
    controls_.reserve(patchCount());
    controls_f_.reserve(patchCount());
    for (size_t p = 0; p < patchCount(); ++p) {
      controls_.push_back(computeControl(recordInputDouble(tri_.mesh, build_, options_, p)));
      controls_f_.push_back(computeControl(recordInputFloat(tri_.mesh, build_, options_, p)));
    }
  }

  techniques::SurfacePoint evaluate(size_t patch,
                                    const techniques::DomainCoord& coord) const override {
    assert(patch < patchCount());
    const PnControl<double>& control = controls_.at(patch);
    const auto& perm = build_.records[patch].perm;
    const PnPoint<double> point =
        evaluateControl(control, {coord[perm[0]], coord[perm[1]], coord[perm[2]]});
    return {point.position, point.normal};
  }

  mesh::Vec3d evaluatePosition(size_t patch, const techniques::DomainCoord& coord) const override {
    assert(patch < patchCount());
    const auto& perm = build_.records[patch].perm;
    return evaluateControlPosition(controls_.at(patch),
                                   {coord[perm[0]], coord[perm[1]], coord[perm[2]]});
  }

  techniques::SurfacePointF evaluateFloat(size_t patch,
                                          const tess::DomainPoint& coord) const override {
    assert(patch < patchCount());
    const PnControl<float>& control = controls_f_[patch];
    const auto& perm = build_.records[patch].perm;
    const PnPoint<float> point =
        evaluateControl(control, {coord[perm[0]], coord[perm[1]], coord[perm[2]]});
    return {point.position, point.normal};
  }

  // The cubic geometry net and its quartic normal patch; the quadratic normal patch gives
  // shading normals only. The net is in label order (labels sorted by position), so its
  // normals face the front when the labels run in the face's winding (perm a rotation of
  // 0, 1, 2) and the back otherwise: then they are negated.
  std::optional<techniques::PatchCullBounds> cullBounds(size_t patch) const override {
    const std::vector<mesh::Vec3d> net = cubicNet(controls_.at(patch));
    std::vector<mesh::Vec3d> normals =
        techniques::withoutZeros(techniques::triangleNormalPatch(3, net));
    const auto& perm = build_.records[patch].perm;
    const bool mirrored = (perm[1] + 3 - perm[0]) % 3 != 1;
    techniques::PatchCullBounds bounds{
        net, mirrored ? techniques::negated(std::move(normals)) : std::move(normals)};
    bounds.bezier_net = net;
    bounds.bezier_degree = 3;
    bounds.bezier_mirrored = mirrored;
    return bounds;
  }

  // curvature_bounds.h on the cubic net, whose corners are labels: domain corner k (weight
  // coord[k]) is the label L with perm[L] = k.
  std::optional<techniques::CurvatureBounds> curvatureBounds(size_t patch) const override {
    const auto& perm = build_.records[patch].perm;
    std::array<int, 3> labels{};
    for (int label = 0; label < 3; ++label) labels[perm[size_t(label)]] = label;
    return techniques::triangleNetCurvatureBounds(cubicNet(controls_.at(patch)), 3, labels);
  }

  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override {
    gpu::GpuPatchProgram program;
    program.control_shader = "pn_triangles/pn.tesc";
    program.evaluation_shader = "pn_triangles/pn.tese";
    program.compute_shader = "pn_triangles/pn.comp";
    program.domain = tess::Domain::kTriangle;
    program.patch_count = uint32_t(patchCount());
    program.input_vertices_per_patch = 1;
    program.storage_buffers = pnStorageBuffers(tri_.mesh, build_);
    program.specialization = {options_.aen ? 1u : 0u,
                              (options_.boundary_flags || options_.rounding > 0) ? 1u : 0u};
    return {program};
  }

  std::optional<techniques::OperationProfile> operationProfile(size_t patch) const override {
    using C = techniques::CountingScalar<float>;
    techniques::OperationProfile profile;
    techniques::resetOperationCounts();
    const PnInput<C> input =
        recordInput<C>(tri_.mesh, build_, options_, patch, [](const mesh::Vec3d& v) {
          return mesh::Vec3T<C>{C(float(v.x)), C(float(v.y)), C(float(v.z))};
        });
    const PnControl<C> control = computeControl(input);
    profile.per_patch_setup = techniques::operationCounts();
    techniques::resetOperationCounts();
    const C third(1.0f / 3.0f);
    (void)evaluateControl(control, {third, third, C(1.0f) - third - third});
    profile.per_vertex = techniques::operationCounts();
    // The evaluation's arguments above are not part of the TES work.
    profile.per_vertex.add -= 2;
    profile.note =
        "float, shader order: TCS normalises the normals it reads and builds 10 + 6 "
        "coefficients; TES evaluates the cubic and quadratic patches and normalises";
    return profile;
  }

  techniques::DataFootprint footprint() const override {
    // Geometry normals add one normal per position; the records are 24 words per patch.
    return {mesh::triangleControlMeshBytes(tri_.mesh),
            uint64_t(build_.geometry_normal_count) * 12 +
                uint64_t(build_.records.size()) * techniques::kRecordWords * 4,
            0};
  }

 private:
  techniques::TriangleRecordOptions options_;
  techniques::TriangleRecords build_;
  std::vector<PnControl<double>> controls_;   // per patch, built once
  std::vector<PnControl<float>> controls_f_;  // the TCS's float nets, per patch
};

}  // namespace

const techniques::TechniqueInfo& PnTrianglesTechnique::info() const {
  static const techniques::TechniqueInfo kInfo{
      "pn_triangles", techniques::TechniqueFamily::kSurface, "Curved PN triangles",
      "Vlachos, Peters, Boyd, Mitchell, Curved PN Triangles, I3D 2001; crack fixes from "
      "CAPCOM's \"Lost Planet 2: DirectX 11 Features\" talk; PN-AEN: McDonald & Kilgard, NVIDIA "
      "2010",
      "triangle meshes with vertex normals; polygons are fan-triangulated; missing normals are "
      "computed"};
  return kInfo;
}

std::vector<techniques::VariantInfo> PnTrianglesTechnique::variants() const {
  return {
      {"pn", "plain PN triangles (shading normals build the geometry)", {}},
      {"geometry_normals",
       "Lost Planet 2 talk: a shared geometry normal per position on split edges (edge flags)",
       {{"geometry_normals", 1}}},
      {"boundary_flags",
       "geometry_normals + the Lost Planet 2 talk's boundary flags: unshared edges stay straight",
       {{"geometry_normals", 1}, {"boundary_flags", 1}}},
      {"aen", "PN-AEN: edge points averaged with the adjacent face's normals", {{"aen", 1}}},
      {"rounding",
       "geometry_normals + the Lost Planet 2 talk's rounding: w_ij scaled by min(1, (1 - Ni.Nj) C "
       "/ L), "
       "C = 4 mean edge lengths",
       {{"geometry_normals", 1}, {"rounding", techniques::kDefaultRounding}}},
  };
}

std::string PnTrianglesTechnique::checkSupport(const mesh::Mesh& mesh) const {
  if (mesh.faceCount() == 0) return "pn_triangles: " + mesh.source + " has no faces";
  if (!mesh.hasNormals()) {
    return "pn_triangles: " + mesh.source + " has no normals (load computes them)";
  }
  for (size_t c = 0; c < mesh.corner_normals.size(); ++c) {
    if (mesh.corner_normals[c] < 0) {
      return "pn_triangles: " + mesh.source + " face corner " + std::to_string(c) +
             " has no normal; every corner needs one";
    }
  }
  return {};
}

std::unique_ptr<techniques::TechniqueInstance> PnTrianglesTechnique::build(
    const techniques::TechniqueInput& input, const techniques::VariantInfo& variant) const {
  const mesh::Mesh& mesh = techniques::requireMesh(info(), input);
  if (std::string reason = checkSupport(mesh); !reason.empty())
    throw techniques::UnsupportedInput(reason);
  // Every switch is off and rounding is 0 unless the variant sets it.
  techniques::TriangleRecordOptions options;
  options.geometry_normals = techniques::paramOr<bool>(info(), variant, "geometry_normals", false);
  options.boundary_flags = techniques::paramOr<bool>(info(), variant, "boundary_flags", false);
  options.aen = techniques::paramOr<bool>(info(), variant, "aen", false);
  options.rounding = techniques::paramOr<double>(info(), variant, "rounding", 0.0);
  return std::make_unique<techniques::SurfaceInstance>(
      std::make_unique<PnPatches>(mesh::fanTriangulate(mesh), options));
}

TB_REGISTER_TECHNIQUE(PnTrianglesTechnique);

}  // namespace tb::pn_triangles
