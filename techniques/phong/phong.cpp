#include "techniques/phong/phong.h"

#include <bit>
#include <cassert>
#include <utility>

#include "core/mesh/render_vertices.h"
#include "core/mesh/triangulate.h"
#include "shaders/phong/phong_layout.h"
#include "techniques/common/triangle_patches.h"
#include "techniques/common/triangle_records.h"
#include "techniques/phong/phong_bounds.h"
#include "techniques/phong/phong_edge_eval.h"
#include "techniques/phong/phong_eval.h"
#include "techniques/registry.h"
#include "techniques/variant_param.h"

namespace tb::phong {
namespace {

// GPU record: label -> corner (3), position (3), normal (3), edge-end normal (6) words.
constexpr uint32_t kPhongRecordWords = gpu::layout::kTbPhongRecordWords;

// The `edge` variant borrows pn_triangles' per-patch records: the canonical corner order
// by position, seed 003's geometry normals and edge flags (a flagged, i.e. split, edge
// uses the geometry normals at its ends; other edges the shading normals).
techniques::TriangleRecordOptions edgeOptions() {
  techniques::TriangleRecordOptions options;
  options.geometry_normals = true;
  return options;
}

class PhongPatches final : public techniques::TrianglePatchesBase {
 public:
  PhongPatches(mesh::Triangulation triangulation, double alpha, bool edge)
      : techniques::TrianglePatchesBase(std::move(triangulation)), alpha_(alpha), edge_(edge) {
    if (edge_) edge_build_ = techniques::buildTriangleRecords(tri_.mesh, edgeOptions());
  }

  techniques::SurfacePoint evaluate(size_t patch,
                                    const techniques::DomainCoord& coord) const override {
    assert(patch < patchCount());
    if (edge_) {
      const auto& perm = edge_build_.records[patch].perm;
      const PhongPoint<double> point =
          evaluatePhongEdge(edgeTriangle<double>(patch, [](const mesh::Vec3d& v) { return v; }),
                            {coord[perm[0]], coord[perm[1]], coord[perm[2]]}, alpha_);
      return {point.position, point.normal};
    }
    const PhongPoint<double> point =
        evaluatePhong(faceTriangle(patch), {coord[0], coord[1], coord[2]}, alpha_);
    return {point.position, point.normal};
  }

  // evaluate() at every point, with the patch's corners (and for plain Phong their canonical
  // order) gathered once: the same operations per point, so the same bits.
  void evaluateBatch(size_t patch, const techniques::BatchPattern& pattern,
                     techniques::BatchPoints& out) const override {
    if (pattern.domain() != techniques::PatchDomain::kTriangle) {
      return evaluateBatchPointByPoint(patch, pattern, out);  // refuses it
    }
    assert(patch < patchCount());
    out.reset(pattern.pointCount());
    const bool normals = pattern.output() != techniques::BatchOutput::kPositions;
    auto store = [&](size_t i, const PhongPoint<double>& point) {
      techniques::BatchPoints::set(out.position, i, point.position);
      if (normals) techniques::BatchPoints::set(out.normal, i, point.normal);
    };
    const std::vector<techniques::DomainCoord>& coords = pattern.coords();
    if (edge_) {
      const auto& perm = edge_build_.records[patch].perm;
      const PhongEdgeTriangle<double> tri =
          edgeTriangle<double>(patch, [](const mesh::Vec3d& v) { return v; });
      for (size_t i = 0; i < coords.size(); ++i) {
        const techniques::DomainCoord& c = coords[i];
        store(i, evaluatePhongEdge(tri, {c[perm[0]], c[perm[1]], c[perm[2]]}, alpha_));
      }
    } else {
      const PhongTriangle<double> tri = faceTriangle(patch);
      const std::array<int, 3> order = canonicalCornerOrder(tri);
      const PhongTriangle<double> sorted = reorderedTriangle(tri, order);
      for (size_t i = 0; i < coords.size(); ++i) {
        const techniques::DomainCoord& c = coords[i];
        store(i, evaluatePhongInOrder(sorted, {c[order[0]], c[order[1]], c[order[2]]}, alpha_));
      }
    }
    out.has_normals = normals;
  }

  techniques::SurfacePointF evaluateFloat(size_t patch,
                                          const tess::DomainPoint& coord) const override {
    assert(patch < patchCount());
    if (edge_) {
      const auto& perm = edge_build_.records[patch].perm;
      const PhongPoint<float> point = evaluatePhongEdge(
          edgeTriangle<float>(patch, [](const mesh::Vec3d& v) { return vecCast<float>(v); }),
          {coord[perm[0]], coord[perm[1]], coord[perm[2]]}, float(alpha_));
      return {point.position, point.normal};
    }
    const mesh::Mesh& mesh = tri_.mesh;
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

  // phong_bounds.h. Plain Phong: the net of the face's corners in face order, whose
  // weights are gl_TessCoord's components, so the normals face the front as they are.
  // The edge variant's hull does not depend on the corner order.
  std::optional<techniques::PatchCullBounds> cullBounds(size_t patch) const override {
    if (edge_) {
      return phongEdgeCullBounds(
          edgeTriangle<double>(patch, [](const mesh::Vec3d& v) { return v; }), alpha_);
    }
    return phongCullBounds(faceTriangle(patch), alpha_);
  }

  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override {
    gpu::GpuPatchProgram program;
    program.control_shader = "phong/phong.tesc";
    program.evaluation_shader = "phong/phong.tese";
    program.compute_shader = "phong/phong.comp";
    program.domain = tess::Domain::kTriangle;
    program.patch_count = uint32_t(patchCount());
    program.input_vertices_per_patch = 1;
    const std::vector<mesh::Vec3d>& normals = edge_ ? edge_build_.normals : tri_.mesh.normals;
    std::vector<uint32_t> records;
    records.reserve(patchCount() * kPhongRecordWords);
    for (size_t p = 0; p < patchCount(); ++p) gpu::layout::appendWords(records, record(p));
    auto vec4s = [](const std::vector<mesh::Vec3d>& values) {
      std::vector<uint32_t> words;
      for (const mesh::Vec3d& v : values) {
        for (float x : {float(v.x), float(v.y), float(v.z), 1.0f}) {
          words.push_back(std::bit_cast<uint32_t>(x));
        }
      }
      return words;
    };
    gpu::setStorageBuffer(program, TB_PHONG_BINDING_POSITIONS, vec4s(tri_.mesh.positions));
    gpu::setStorageBuffer(program, TB_PHONG_BINDING_NORMALS, vec4s(normals));
    gpu::setStorageBuffer(program, TB_PHONG_BINDING_RECORDS, std::move(records));
    program.specialization = {std::bit_cast<uint32_t>(float(alpha_)), edge_ ? 1u : 0u};
    return {program};
  }

  std::optional<techniques::OperationProfile> operationProfile(size_t patch) const override {
    using C = techniques::CountingScalar<float>;
    auto cast = [](const mesh::Vec3d& v) {
      return mesh::Vec3T<C>{C(float(v.x)), C(float(v.y)), C(float(v.z))};
    };
    const C third(1.0f / 3.0f);
    const std::array<C, 3> weight{third, third, C(1.0f / 3.0f)};
    techniques::OperationProfile profile;
    techniques::resetOperationCounts();
    if (edge_) {
      const PhongEdgeTriangle<C> tri = edgeTriangle<C>(patch, cast);
      profile.per_patch_setup = techniques::operationCounts();
      techniques::resetOperationCounts();
      (void)evaluatePhongEdge(tri, weight, C(float(alpha_)));
      profile.note = "float, shader order: TCS normalises 3 + 6 normals; TES per-edge offsets";
    } else {
      const mesh::Mesh& mesh = tri_.mesh;
      const uint32_t first = mesh.face_offsets[patch];
      PhongTriangle<C> tri;
      for (int i = 0; i < 3; ++i) {
        tri.position[i] = cast(mesh.positions[mesh.corner_positions[first + i]]);
        tri.normal[i] = normalize(cast(mesh.normals[mesh.corner_normals[first + i]]));
      }
      profile.per_patch_setup = techniques::operationCounts();
      techniques::resetOperationCounts();
      (void)evaluatePhongInOrder(tri, weight, C(float(alpha_)));
      profile.note =
          "float, shader order: TCS normalises 3 normals (corner order sorted on the "
          "host); TES eq. 3-4";
    }
    profile.per_vertex = techniques::operationCounts();
    return profile;
  }

  techniques::DataFootprint footprint() const override {
    // Phong needs nothing beyond the vertex buffer and index buffer; the edge variant adds
    // a geometry normal per position and 4 bytes of edge flags per vertex (seed 003).
    if (!edge_) return {mesh::triangleControlMeshBytes(tri_.mesh), 0, 0};
    return {mesh::triangleControlMeshBytes(tri_.mesh),
            uint64_t(edge_build_.geometry_normal_count) * 12 + patchCount() * 3 * 4, 0};
  }

 private:
  using PatchRecord = gpu::layout::TbPhongRecord;

  // The GPU record of patch p: canonical order (canonicalCornerOrder on the float corners,
  // as evaluateFloat sorts them; pn_triangles' order for the edge variant) and indices.
  PatchRecord record(size_t patch) const {
    PatchRecord r{};
    const mesh::Mesh& mesh = tri_.mesh;
    const uint32_t first = mesh.face_offsets[patch];
    if (edge_) {
      const techniques::TriangleRecord& pr = edge_build_.records[patch];
      for (int i = 0; i < 3; ++i) {
        r.perm[i] = pr.perm[i];
        r.position[i] = pr.position[i];
        r.normal[i] = pr.normal[i];
      }
      for (int e = 0; e < 3; ++e) {
        for (int end = 0; end < 2; ++end) r.edge_normal[2 * e + end] = edgeNormalIndex(pr, e, end);
      }
      return r;
    }
    PhongTriangle<float> tri;
    for (int i = 0; i < 3; ++i) {
      tri.position[i] = vecCast<float>(mesh.positions[mesh.corner_positions[first + i]]);
      tri.normal[i] = normalize(vecCast<float>(mesh.normals[mesh.corner_normals[first + i]]));
    }
    const std::array<int, 3> order = canonicalCornerOrder(tri);
    for (int i = 0; i < 3; ++i) {
      r.perm[i] = uint32_t(order[i]);
      r.position[i] = mesh.corner_positions[first + order[i]];
      r.normal[i] = uint32_t(mesh.corner_normals[first + order[i]]);
    }
    for (int k = 0; k < 6; ++k) r.edge_normal[k] = r.normal[0];  // unused without the edge variant
    return r;
  }

  // Patch p's corners in face order, double, unit normals.
  PhongTriangle<double> faceTriangle(size_t patch) const {
    const mesh::Mesh& mesh = tri_.mesh;
    const uint32_t first = mesh.face_offsets[patch];
    PhongTriangle<double> tri;
    for (int i = 0; i < 3; ++i) {
      tri.position[i] = mesh.positions[mesh.corner_positions[first + i]];
      tri.normal[i] = normalize(mesh.normals[mesh.corner_normals[first + i]]);
    }
    return tri;
  }

  static uint32_t edgeNormalIndex(const techniques::TriangleRecord& r, int e, int end) {
    const int a = kPhongEdgeEnds[e][0], b = kPhongEdgeEnds[e][1];
    const int label = kPhongEdgeEnds[e][end];
    const bool flagged = ((r.flags[a] & r.flags[b]) & (1u << e)) != 0;
    return flagged ? r.geometry_normal[label] : r.normal[label];
  }

  template <class T, class Cast>
  PhongEdgeTriangle<T> edgeTriangle(size_t patch, Cast cast) const {
    const techniques::TriangleRecord& r = edge_build_.records[patch];
    PhongEdgeTriangle<T> tri;
    for (int i = 0; i < 3; ++i) {
      tri.position[i] = cast(tri_.mesh.positions[r.position[i]]);
      tri.normal[i] = normalize(cast(edge_build_.normals[r.normal[i]]));
    }
    for (int e = 0; e < 3; ++e) {
      for (int end = 0; end < 2; ++end) {
        tri.edge_normal[e][end] = normalize(cast(edge_build_.normals[edgeNormalIndex(r, e, end)]));
      }
    }
    return tri;
  }

  double alpha_;
  bool edge_;
  techniques::TriangleRecords edge_build_;
};

}  // namespace

const techniques::TechniqueInfo& PhongTechnique::info() const {
  static const techniques::TechniqueInfo kInfo{
      "phong", techniques::TechniqueFamily::kSurface, "Phong tessellation",
      "Boubekeur & Alexa, Phong Tessellation, ACM TOG 27(5) (SIGGRAPH Asia 2008)",
      "triangle meshes with vertex normals; polygons are fan-triangulated; missing normals are "
      "computed"};
  return kInfo;
}

std::vector<techniques::VariantInfo> PhongTechnique::variants() const {
  // Default first: the paper's α = 3/4. The α sweep (0, 0.5, 1) runs in --suite full only:
  // its three error records on the pawns were a fifth of the default suite's error time.
  return {
      {"alpha0.75", "shape factor 0.75 (the paper's choice)", {{"alpha", 0.75}}},
      {"alpha0", "shape factor 0: the flat triangle", {{"alpha", 0.0}}, false, true},
      {"alpha0.5", "shape factor 0.5", {{"alpha", 0.5}}, false, true},
      {"alpha1", "shape factor 1: full projection", {{"alpha", 1.0}}, false, true},
      {"edge",
       "the per-edge extension of CAPCOM's Lost Planet 2 DirectX 11 talk (α = 0.75): edge curves "
       "from per-edge normals, "
       "geometry normals on split edges",
       {{"alpha", 0.75}, {"edge", 1.0}}},
  };
}

std::string PhongTechnique::checkSupport(const mesh::Mesh& mesh) const {
  if (mesh.faceCount() == 0) return "phong: " + mesh.source + " has no faces";
  if (!mesh.hasNormals()) return "phong: " + mesh.source + " has no normals (load computes them)";
  return {};
}

std::unique_ptr<techniques::TechniqueInstance> PhongTechnique::build(
    const techniques::TechniqueInput& input, const techniques::VariantInfo& variant) const {
  const mesh::Mesh& mesh = techniques::requireMesh(info(), input);
  if (std::string reason = checkSupport(mesh); !reason.empty())
    throw techniques::UnsupportedInput(reason);
  return std::make_unique<techniques::SurfaceInstance>(std::make_unique<PhongPatches>(
      mesh::fanTriangulate(mesh),
      techniques::paramOr<double>(info(), variant, "alpha", kDefaultAlpha),
      techniques::paramOr<bool>(info(), variant, "edge", false)));
}

TB_REGISTER_TECHNIQUE(PhongTechnique);

}  // namespace tb::phong
