#include "techniques/acc/acc.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <map>
#include <numbers>
#include <tuple>
#include <utility>

#include "shaders/acc/acc_layout.h"
#include "techniques/acc/acc_batch.h"
#include "techniques/acc/acc_patch.h"
#include "techniques/common/crease_refinement.h"
#include "techniques/common/patch_bounds.h"
#include "techniques/common/quad_ring.h"
#include "techniques/registry.h"
#include "techniques/variant_param.h"

namespace tb::acc {

CornerWeights cornerWeights(uint32_t valence, bool boundary, bool corner) {
  CornerWeights w;
  const double n = boundary ? 4.0 : double(valence);  // boundary: the valence-4 masks
  w.ev = 2 * n / (2 * n + 10);
  w.ee = 4 / (2 * n + 10);
  w.ea = 2 / (2 * n + 10);
  w.ef = 1 / (2 * n + 10);
  w.iv = n / (n + 5);
  w.ie = 2 / (n + 5);
  w.iff = 1 / (n + 5);
  w.bv = 2.0 / 3.0;
  w.be = 1.0 / 3.0;
  if (boundary) {
    // Boundary B-spline corner (e_0 + 4 v + e_{n-1}) / 6; a corner interpolates.
    w.cv = corner ? 1.0 : 4.0 / 6.0;
    w.ce = corner ? 0.0 : 1.0 / 6.0;
    w.cosine = 0;
  } else {
    w.cv = n / (n + 5);
    w.ce = 4 / (n * (n + 5));
    w.cf = 1 / (n * (n + 5));
    // cos(2π/4) is exactly 0: regular corners then keep the B-spline tangents bit for bit.
    w.cosine = valence == 4 ? 0.0 : std::cos(2 * std::numbers::pi / n);
  }
  return w;
}

std::vector<double> tangentMask(uint32_t valence) {
  const double n = valence;
  const double cp = std::cos(std::numbers::pi / n);
  const double radical = std::sqrt(4 + cp * cp);
  const double beta = 1 / (n * radical);
  const double alpha = 1 / n + cp * beta;
  std::vector<double> mask(2 * valence);
  for (uint32_t j = 0; j < valence; ++j) {
    mask[j] = alpha * std::cos(2 * std::numbers::pi * j / n);
    mask[valence + j] = beta * std::cos((2 * j + 1) * std::numbers::pi / n);
  }
  return mask;
}

namespace {

using KindKey = std::tuple<uint32_t, bool, bool>;  // (valence, boundary, corner)
using ClassKey = std::array<KindKey, 4>;

// Checks the input (quads, manifold edges) and what the crease preparation cannot
// represent; throws UnsupportedInput.
void validate(const mesh::Mesh& mesh) {
  techniques::requireManifoldQuads(mesh, "acc", "ACC needs quads", "ACC needs a manifold mesh");
}

void validateCreases(const techniques::CreasePreparation& creases) {
  for (size_t v = 0; v < creases.vertex_kind.size(); ++v) {
    if (creases.vertex_kind[v] == techniques::SharpVertexKind::kCone) {
      throw techniques::UnsupportedInput(
          "acc: " + techniques::describeVertex(creases.control, uint32_t(v)) +
          " is an infinitely sharp corner with fewer than two sharp edges "
          "(a cone point); ACC patches cannot represent it");
    }
  }
  if (creases.patch_faces == 0) {
    throw techniques::UnsupportedInput("acc: " + creases.control.source +
                                       " has no face with a limit surface");
  }
}

// The crease preparation of a mesh for acc (validate first).
techniques::CreasePreparation prepare(const mesh::Mesh& mesh, size_t face_budget) {
  techniques::CreasePreparation creases = techniques::prepareCreases(mesh, "acc", face_budget);
  validateCreases(creases);
  return creases;
}

class AccPatches final : public techniques::SurfacePatches {
 public:
  AccPatches(techniques::CreasePreparation creases, techniques::BezierOrder order,
             bool tangent_patches)
      : creases_(std::move(creases)),
        mesh_(creases_.control),
        order_(order),
        tangent_(tangent_patches) {
    rings_ = techniques::buildQuadRings(mesh_, "acc", kMaxValence, &creases_);
    // Ring r's centre position (an extra sector repeats its vertex's position).
    for (const techniques::VertexRing& ring : rings_.rings)
      ring_positions_.push_back(mesh_.positions[ring.vertex]);
    const size_t patches = creases_.patch_faces;
    corners_.resize(patches);
    class_of_.resize(patches);
    rotation_of_.resize(patches);
    std::map<ClassKey, uint32_t> class_index;
    for (size_t p = 0; p < patches; ++p) {
      ClassKey key;
      for (int k = 0; k < 4; ++k) {
        const uint32_t ring_index = rings_.face_rings[p][k];
        const techniques::VertexRing& ring = rings_.rings[ring_index];
        const KindKey kind{ring.valence, ring.boundary, ring.corner};
        key[k] = kind;
        auto [it, inserted] = weights_.try_emplace(kind);
        if (inserted) it->second = cornerWeights(ring.valence, ring.boundary, ring.corner);
        const std::vector<double>* mask = nullptr;
        if (!ring.boundary) {
          auto [m, fresh] = masks_.try_emplace(ring.valence);
          if (fresh) m->second = tangentMask(ring.valence);
          mask = &m->second;
        }
        corners_[p][k] = {ring_index, rings_.face_slots[p][k], &it->second, mask};
      }
      // Topology combination: the corner kinds up to rotation (smallest rotation).
      ClassKey best = key;
      uint32_t best_rotation = 0;
      for (uint32_t r = 1; r < 4; ++r) {
        ClassKey rotated;
        for (int k = 0; k < 4; ++k) rotated[k] = key[(k + r) % 4];
        if (rotated < best) best = rotated, best_rotation = r;
      }
      const auto [it, inserted] = class_index.try_emplace(best, uint32_t(classes_.size()));
      if (inserted) classes_.push_back(best);
      class_of_[p] = it->second;
      rotation_of_[p] = best_rotation;  // patch corner k is class corner (k + 4 - r) % 4
    }
    const auto position_d = [this](uint32_t i) { return ring_positions_[i]; };
    const auto position_f = [this](uint32_t i) { return vecCast<float>(ring_positions_[i]); };
    points_d_.resize(patches);
    points_f_.resize(patches);
    for (size_t p = 0; p < patches; ++p) {
      points_d_[p] = accControlPoints<double>(rings_, corners_[p], tangent_, position_d);
      points_f_[p] = accControlPoints<float>(rings_, corners_[p], tangent_, position_f);
    }
    warnings_ = creases_.notes;
    warnings_.push_back(std::to_string(patches) + " patches in " + std::to_string(classes_.size()) +
                        " topology combinations (corner valence and boundary, up to rotation)");
  }

  techniques::PatchDomain patchDomain(size_t) const override {
    return techniques::PatchDomain::kQuad;
  }
  size_t patchCount() const override { return creases_.patch_faces; }
  // The input, or the input refined until its semi-sharp creases have decayed, with its
  // holes last: face p is patch p for p < patchCount().
  const mesh::Mesh& controlMesh() const override { return mesh_; }
  std::array<uint32_t, 4> patchCorners(size_t patch) const override {
    const auto face = mesh_.facePositions(patch);
    return {face[0], face[1], face[2], face[3]};
  }
  uint32_t sourceFace(size_t patch) const override { return creases_.source_face[patch]; }

  techniques::SurfacePoint evaluate(size_t patch,
                                    const techniques::DomainCoord& coord) const override {
    assert(patch < patchCount());
    const AccControlPoints<double>& p = points_d_[patch];
    const double u = coord[0], v = coord[1];
    const mesh::Vec3d tu = techniques::evaluateTangentU(p.tu, u, v),
                      tv = techniques::evaluateTangentV(p.tv, u, v);
    return {techniques::evaluateBicubicFast(p.b, u, v, order_), normalize(cross(tu, tv))};
  }

  // The geometry patch alone: the tangent patches give only the normal.
  mesh::Vec3d evaluatePosition(size_t patch, const techniques::DomainCoord& coord) const override {
    assert(patch < patchCount());
    return techniques::evaluateBicubicFast(points_d_[patch].b, coord[0], coord[1], order_);
  }

  std::unique_ptr<techniques::BatchPattern> makeBatchPattern(
      techniques::PatchDomain domain, std::vector<techniques::DomainCoord> coords,
      techniques::BatchOutput output) const override {
    if (domain != techniques::PatchDomain::kQuad) {  // fits no acc patch; evaluateBatch refuses it
      return techniques::SurfacePatches::makeBatchPattern(domain, std::move(coords), output);
    }
    return std::make_unique<AccBatchPattern>(std::move(coords), output);
  }

  void evaluateBatch(size_t patch, const techniques::BatchPattern& pattern,
                     techniques::BatchPoints& out) const override {
    assert(patch < patchCount());
    const auto* acc = dynamic_cast<const AccBatchPattern*>(&pattern);
    if (acc == nullptr) return evaluateBatchPointByPoint(patch, pattern, out);
    acc->evaluate(points_d_[patch], out);
  }

  techniques::SurfacePointF evaluateFloat(size_t patch,
                                          const tess::DomainPoint& coord) const override {
    assert(patch < patchCount());
    const AccControlPoints<float>& p = points_f_[patch];
    const float u = coord[0], v = coord[1];
    const mesh::Vec3f tu = techniques::evaluateTangentU(p.tu, u, v),
                      tv = techniques::evaluateTangentV(p.tv, u, v);
    return {techniques::evaluateBicubic(p.b, u, v, order_), normalize(cross(tu, tv))};
  }

  std::optional<techniques::OperationProfile> operationProfile(size_t patch) const override {
    using C = techniques::CountingScalar<float>;
    const auto position = [&](uint32_t i) {
      const mesh::Vec3d& q = ring_positions_[i];
      return mesh::Vec3T<C>{C(float(q.x)), C(float(q.y)), C(float(q.z))};
    };
    techniques::OperationProfile profile;
    techniques::resetOperationCounts();
    const AccControlPoints<C> p = accControlPoints<C>(rings_, corners_[patch], tangent_, position);
    profile.per_patch_setup = techniques::operationCounts();
    techniques::resetOperationCounts();
    const C u(0.3f), v(0.6f);
    const mesh::Vec3T<C> position_uv = techniques::evaluateBicubic(p.b, u, v, order_);
    const mesh::Vec3T<C> normal = normalize(
        cross(techniques::evaluateTangentU(p.tu, u, v), techniques::evaluateTangentV(p.tv, u, v)));
    (void)position_uv;
    (void)normal;
    profile.per_vertex = techniques::operationCounts();
    bool regular = true;
    for (const PatchCorner& c : corners_[patch]) {
      const techniques::VertexRing& ring = rings_.rings[c.vertex];
      regular = regular && !ring.boundary && ring.valence == 4;
    }
    profile.note = std::string(regular ? "regular" : "irregular") + " patch, " +
                   (tangent_ ? "tangent patches" : "geometry derivatives") +
                   ", fma counted as one mul and one add";
    return profile;
  }

  // The bicubic geometry patch's control net and its normal patch; the tangent patches
  // give shading normals only. The domain runs (0,0), (1,0), (1,1), (0,1) through face
  // corners 0, 1, 2, 3 (kCornerPoint), the face's own winding, so p_u x p_v faces the
  // front as it is.
  std::optional<techniques::PatchCullBounds> cullBounds(size_t patch) const override {
    const std::array<mesh::Vec3d, 16>& b = points_d_[patch].b;
    techniques::PatchCullBounds bounds{{b.begin(), b.end()},
                                       techniques::withoutZeros(techniques::bicubicNormalPatch(b))};
    bounds.bezier_net = bounds.hull;
    bounds.bezier_degree = 3;
    return bounds;
  }

  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override;

  techniques::DataFootprint footprint() const override {
    techniques::DataFootprint f;
    // GPU layout of gpuPrograms(): vec4 positions; per vertex a 16-byte ring header
    // and 8 bytes per ring slot; 48 bytes per patch; the stencil table.
    f.control_mesh_bytes = 16ull * mesh_.positions.size();
    f.patch_data_bytes =
        16ull * rings_.rings.size() + 8ull * rings_.edge_neighbours.size() + 48ull * patchCount();
    f.stencil_bytes = 4ull * stencilFloatCount();
    f.topology_combinations = classes_.size();
    return f;
  }

  const std::vector<std::string>& warnings() const override { return warnings_; }
  size_t combinationCount() const { return classes_.size(); }

 private:
  size_t stencilFloatCount() const {
    size_t masks = 0;
    for (const auto& [valence, mask] : masks_) masks += mask.size();
    return classes_.size() * 4 * kCornerWeightFloats + masks;
  }

  techniques::CreasePreparation creases_;
  const mesh::Mesh& mesh_;  // creases_.control
  std::vector<mesh::Vec3d> ring_positions_;
  techniques::BezierOrder order_;
  bool tangent_;
  techniques::QuadRings rings_;
  std::map<KindKey, CornerWeights> weights_;
  std::map<uint32_t, std::vector<double>> masks_;
  std::vector<std::array<PatchCorner, 4>> corners_;
  std::vector<ClassKey> classes_;
  std::vector<uint32_t> class_of_, rotation_of_;
  std::vector<AccControlPoints<double>> points_d_;
  std::vector<AccControlPoints<float>> points_f_;
  std::vector<std::string> warnings_;
};

uint32_t floatBits(double value) { return std::bit_cast<uint32_t>(float(value)); }

std::vector<gpu::GpuPatchProgram> AccPatches::gpuPrograms() const {
  gpu::GpuPatchProgram program;
  program.control_shader = "acc/acc.tesc";
  program.evaluation_shader = "acc/acc.tese";
  program.compute_shader = "acc/acc.comp";
  program.domain = tess::Domain::kQuad;
  program.patch_count = uint32_t(patchCount());
  program.input_vertices_per_patch = 1;
  std::vector<uint32_t> positions, headers, slots, patches, stencils;
  for (const mesh::Vec3d& p : ring_positions_) {
    for (double x : {p.x, p.y, p.z, 0.0}) positions.push_back(floatBits(x));
  }
  // Stencil table: per class 4 corners x kCornerWeightFloats, then the tangent masks.
  for (const ClassKey& key : classes_) {
    for (const KindKey& kind : key) {
      const CornerWeights& w = weights_.at(kind);
      const double values[kCornerWeightFloats] = {w.cv,     w.ce, w.cf, w.ev,  w.ee, w.ea,
                                                  w.ef,     w.iv, w.ie, w.iff, w.bv, w.be,
                                                  w.cosine, 0,    0,    0};
      for (double x : values) stencils.push_back(floatBits(x));
    }
  }
  std::map<uint32_t, uint32_t> mask_offset;
  for (const auto& [valence, mask] : masks_) {
    mask_offset[valence] = uint32_t(stencils.size());
    for (double x : mask) stencils.push_back(floatBits(x));
  }
  for (const techniques::VertexRing& ring : rings_.rings) {
    const auto m = mask_offset.find(ring.valence);
    headers.insert(headers.end(), {ring.offset, ring.valence, ring.boundary ? 1u : 0u,
                                   ring.boundary || m == mask_offset.end() ? 0u : m->second});
  }
  for (size_t i = 0; i < rings_.edge_neighbours.size(); ++i) {
    slots.push_back(rings_.edge_neighbours[i]);
    slots.push_back(rings_.diagonals[i]);
  }
  for (size_t p = 0; p < patchCount(); ++p) {
    for (const PatchCorner& c : corners_[p]) patches.push_back(c.vertex);
    for (const PatchCorner& c : corners_[p]) patches.push_back(c.slot);
    patches.insert(patches.end(), {class_of_[p], rotation_of_[p], 0u, 0u});
  }
  if (slots.empty()) slots.push_back(0);
  gpu::setStorageBuffer(program, TB_ACC_BINDING_POSITIONS, std::move(positions));
  gpu::setStorageBuffer(program, TB_ACC_BINDING_RING_HEADERS, std::move(headers));
  gpu::setStorageBuffer(program, TB_ACC_BINDING_RING_SLOTS, std::move(slots));
  gpu::setStorageBuffer(program, TB_ACC_BINDING_PATCHES, std::move(patches));
  gpu::setStorageBuffer(program, TB_ACC_BINDING_STENCILS, std::move(stencils));
  program.specialization = {uint32_t(order_), tangent_ ? 1u : 0u};
  return {program};
}

}  // namespace

const techniques::TechniqueInfo& AccTechnique::info() const {
  static const techniques::TechniqueInfo kInfo{
      "acc", techniques::TechniqueFamily::kSurface,
      "Approximate Catmull-Clark (bicubic geometry + tangent patches)",
      "Loop & Schaefer, Approximating Catmull-Clark Subdivision Surfaces with Bicubic Patches, "
      "ACM TOG 27(1) 2008",
      "manifold all-quad meshes, valence <= 256; creases, corners, holes and every boundary "
      "interpolation (semi-sharp creases refined with OpenSubdiv until they decay, within a "
      "face budget); no cone points (a sharp vertex tag off a crease)"};
  return kInfo;
}

std::vector<techniques::VariantInfo> AccTechnique::variants() const {
  // Every variant but default and no_tangent only reorders the float evaluation of the
  // default's patches (VariantInfo::evaluation_order_only).
  const auto make = [](std::string name, std::string text, techniques::BezierOrder order,
                       bool tangent) {
    const bool reorders = order != techniques::BezierOrder::kSymmetricFma;
    return techniques::VariantInfo{
        std::move(name),
        std::move(text),
        {{"order", double(int(order))}, {"tangent", tangent ? 1.0 : 0.0}},
        reorders};
  };
  std::vector<techniques::VariantInfo> variants{
      make("default", "tangent patches; symmetric FMA Bézier order",
           techniques::BezierOrder::kSymmetricFma, true),
      make("no_tangent", "normal from the geometry patch's derivatives; symmetric FMA order",
           techniques::BezierOrder::kSymmetricFma, false),
      make("asymmetric", "tangent patches; FMA chain along u then v (not watertight)",
           techniques::BezierOrder::kAsymmetric, true),
      make("symmetric_nofma", "tangent patches; symmetric order without FMA",
           techniques::BezierOrder::kSymmetricNoFma, true),
      make("symmetric_edges", "tangent patches; symmetric FMA order on the edge rows only",
           techniques::BezierOrder::kSymmetricEdges, true),
      make("symmetric_imprecise",
           "symmetric order without FMA, written without `precise` (the compiler may "
           "reassociate it)",
           techniques::BezierOrder::kSymmetricNoFmaImprecise, true),
  };
  variants[2].control = "shared edges evaluated in patch order crack in float";
  variants[5].control = "without `precise` the compiler may reassociate the symmetric order";
  return variants;
}

techniques::BezierOrder variantOrder(const techniques::VariantInfo& variant) {
  return techniques::paramOr<techniques::BezierOrder>(AccTechnique().info(), variant, "order",
                                                      techniques::BezierOrder::kSymmetricFma);
}

bool variantTangentPatches(const techniques::VariantInfo& variant) {
  return techniques::paramOr<bool>(AccTechnique().info(), variant, "tangent", true);
}

size_t variantCreaseFaceBudget(const techniques::VariantInfo& variant) {
  return size_t(std::max(
      1.0, techniques::paramOr<double>(AccTechnique().info(), variant, "crease_face_budget",
                                       double(techniques::kDefaultCreaseFaceBudget))));
}

std::string AccTechnique::checkSupport(const mesh::Mesh& mesh) const {
  try {
    validate(mesh);
    const techniques::CreasePreparation creases =
        prepare(mesh, techniques::kDefaultCreaseFaceBudget);
    techniques::buildQuadRings(creases.control, "acc", kMaxValence, &creases);
  } catch (const techniques::UnsupportedInput& error) {
    return error.what();
  }
  return {};
}

std::unique_ptr<techniques::TechniqueInstance> AccTechnique::build(
    const techniques::TechniqueInput& input, const techniques::VariantInfo& variant) const {
  const mesh::Mesh& mesh = techniques::requireMesh(info(), input);
  validate(mesh);
  return std::make_unique<techniques::SurfaceInstance>(
      std::make_unique<AccPatches>(prepare(mesh, variantCreaseFaceBudget(variant)),
                                   variantOrder(variant), variantTangentPatches(variant)));
}

size_t topologyCombinationCount(const techniques::SurfacePatches& patches) {
  const auto* acc = dynamic_cast<const AccPatches*>(&patches);
  return acc == nullptr ? 0 : acc->combinationCount();
}

TB_REGISTER_TECHNIQUE(AccTechnique);

}  // namespace tb::acc
