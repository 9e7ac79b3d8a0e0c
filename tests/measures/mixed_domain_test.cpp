// The measures on patches that mix quad and triangle domains (one SurfacePatches over
// catmark_pyramid: 4 triangles and 1 quad), against independent oracles: hand counts of
// the pyramid's shared edges and corners and the tessellator's own edge point count;
// Euler's formula for the closed seamless welded mesh; the tessellator's per-domain
// triangle counts; and for the error measure the Catmull-Clark limit evaluated through
// Bfr's face (u,v) at a sub-face point found by an inverse bilinear solve written here
// (the measure maps forward), which must give zero parametric error.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/mesh/obj_loader.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/measures/error/error.h"
#include "harness/measures/measure.h"
#include "harness/measures/memory/memory.h"
#include "reference/face_domain.h"
#include "reference/limit_surface.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/measures/face_patches.h"
#include "tests/test_support.h"

namespace tb {
namespace {

mesh::Mesh pyramid() {
  return mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_pyramid.obj"));
}

// Patch p is face p of a Catmull-Clark mesh, in the face's own domain. Subclasses give
// the surface.
class MixedPatches : public testing::FacePatches {
 public:
  using FacePatches::FacePatches;
  techniques::LimitScheme approximates() const override {
    return techniques::LimitScheme::kCatmullClark;
  }
};

mesh::Vec3f lerp(const mesh::Vec3f& a, const mesh::Vec3f& b, float t) {
  return a * (1 - t) + b * t;
}

// Flat patches: bilinear quads, linear triangles. On an edge both kinds evaluate
// lerp(corner e, corner e + 1, t) with t the edge parameter (from the other side t is
// exactly 1 - t, and the sum commutes), so shared points match bit for bit. `perturb`
// moves every boundary point of the triangle patches one float step in x.
class FlatMixedPatches final : public MixedPatches {
 public:
  FlatMixedPatches(mesh::Mesh mesh, bool perturb)
      : MixedPatches(std::move(mesh)), perturb_(perturb) {}
  techniques::SurfacePoint evaluate(size_t patch, const techniques::DomainCoord& c) const override {
    const techniques::SurfacePointF f =
        evaluateFloat(patch, {float(c[0]), float(c[1]), float(c[2])});
    return {vecCast<double>(f.position), {0, 0, 1}};
  }
  techniques::SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& c) const override {
    const mesh::Vec3f p0 = cornerF(patch, 0), p1 = cornerF(patch, 1), p2 = cornerF(patch, 2);
    if (patchDomain(patch) == techniques::PatchDomain::kQuad) {
      const mesh::Vec3f p3 = cornerF(patch, 3);
      return {lerp(lerp(p0, p1, c[0]), lerp(p3, p2, c[0]), c[1]), {0, 0, 1}};
    }
    mesh::Vec3f p;
    if (c[2] == 0) {
      p = lerp(p0, p1, c[1]);
    } else if (c[0] == 0) {
      p = lerp(p1, p2, c[2]);
    } else if (c[1] == 0) {
      p = lerp(p2, p0, c[0]);
    } else {
      return {p0 * c[0] + p1 * c[1] + p2 * c[2], {0, 0, 1}};
    }
    if (perturb_) p.x = std::nextafter(p.x, INFINITY);
    return {p, {0, 0, 1}};
  }

 private:
  bool perturb_;
};

constexpr tess::Spacing kSpacings[] = {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd,
                                       tess::Spacing::kFractionalEven, tess::Spacing::kPow2};
constexpr float kLevels[] = {1.0f, 7.3f, 16.0f, 64.0f};

// Tessellated points strictly inside one edge of `domain`, counted on local edge 0.
uint64_t edgeInteriorPoints(tess::Domain domain, tess::Spacing spacing, float level) {
  const tess::Tessellation t =
      tess::tessellate(domain, spacing, {{level, level, level, level}, {level, level}});
  uint64_t count = 0;
  for (const tess::DomainPoint& p : t.points) {
    const bool on_edge0 = domain == tess::Domain::kQuad ? p[1] == 0 : p[2] == 0;
    const float t_edge = domain == tess::Domain::kQuad ? p[0] : p[1];
    count += on_edge0 && t_edge > 0 && t_edge < 1;
  }
  return count;
}

TEST(MixedDomains, PyramidSharesItsEightEdgesAndFiveCornersAcrossQuadAndTriangles) {
  const FlatMixedPatches patches(pyramid(), false);
  const measures::SharedBoundaries shared = measures::findSharedBoundaries(patches);
  ASSERT_EQ(shared.edges.size(), 8u);  // 4 slanted edges (tri-tri), 4 base edges (tri-quad)
  ASSERT_EQ(shared.corners.size(), 5u);
  int quad_triangle_edges = 0;
  for (const measures::SharedEdge& edge : shared.edges) {
    ASSERT_EQ(edge.sides.size(), 2u);
    quad_triangle_edges += edge.sides[1].patch == 4;  // the quad is the last face
  }
  EXPECT_EQ(quad_triangle_edges, 4);
  for (const measures::SharedCorner& corner : shared.corners) {
    // The apex (position 0) is on 4 triangles; each base vertex on 2 triangles and the quad.
    EXPECT_EQ(corner.sides.size(), corner.vertex == 0 ? 4u : 3u);
  }
}

TEST(MixedDomains, EdgeSymmetricPatchesAreBitwiseWatertightUnderEverySpacing) {
  const FlatMixedPatches patches(pyramid(), false);
  for (tess::Spacing spacing : kSpacings) {
    for (float level : kLevels) {
      SCOPED_TRACE(std::string(tess::toString(spacing)) + " level " + std::to_string(level));
      const measures::CrackFigures f =
          measures::measureCracks(patches, spacing, level, measures::CrackBackend::kCpuFloat);
      ASSERT_TRUE(f.measured) << f.skipped_reason;
      // Both domains split an edge alike, so every point of an edge has its mirror.
      const uint64_t per_edge = edgeInteriorPoints(tess::Domain::kQuad, spacing, level);
      EXPECT_EQ(per_edge, edgeInteriorPoints(tess::Domain::kTriangle, spacing, level));
      EXPECT_EQ(f.points_compared, 8 * per_edge + 3 + 4 * 2);  // edges, apex, base corners
      EXPECT_EQ(f.unpaired_points, 0u);
      EXPECT_EQ(f.points_not_equal, 0u);
      EXPECT_EQ(f.max_gap_world, 0.0);
    }
  }
}

TEST(MixedDomains, APerturbedTriangleSideShowsUpAsUnequalPoints) {
  const FlatMixedPatches patches(pyramid(), true);
  const float level = 7.3f;
  const measures::CrackFigures f = measures::measureCracks(
      patches, tess::Spacing::kFractionalOdd, level, measures::CrackBackend::kCpuFloat);
  ASSERT_TRUE(f.measured);
  EXPECT_EQ(f.unpaired_points, 0u);
  // Tri-quad edges and corners where a triangle meets the quad differ by one float step;
  // tri-tri points are moved alike on both sides (except where a triangle meets the quad).
  const uint64_t per_edge =
      edgeInteriorPoints(tess::Domain::kQuad, tess::Spacing::kFractionalOdd, level);
  EXPECT_EQ(f.points_not_equal, 4 * per_edge + 4);
  EXPECT_EQ(f.max_gap_ulp, 1u);
  EXPECT_GT(f.max_gap_world, 0.0);
}

// --- memory ---------------------------------------------------------------------------

TEST(MixedDomains, ClosedFormMatchesTheWeldedMeshAndEuler) {
  mesh::Mesh mesh = pyramid();
  for (bool uvs : {true, false}) {
    if (!uvs) std::fill(mesh.corner_uvs.begin(), mesh.corner_uvs.end(), -1);
    const FlatMixedPatches patches(mesh, false);
    for (uint32_t level : {1u, 2u, 5u, 8u}) {
      SCOPED_TRACE("uvs " + std::to_string(uvs) + " level " + std::to_string(level));
      const measures::MemoryFigures m = measures::measureMemory(patches, level);
      const measures::TessellatedMesh built = measures::buildTessellatedMesh(patches, level);
      EXPECT_EQ(m.plain_vertices, built.vertexCount());
      EXPECT_EQ(m.plain_triangles, built.indices.size() / 3);
      // Per-domain sums: 4 triangle patches and one quad patch.
      EXPECT_EQ(m.plain_triangles,
                4 * tess::triangleTriangleCount(level) + tess::quadTriangleCount(level));
      EXPECT_EQ(m.displacement_bytes, 2 * (4 * uint64_t(level + 1) * (level + 2) / 2 +
                                           uint64_t(level + 1) * (level + 1)));
      // A closed seamless triangle mesh of genus 0: V = F / 2 + 2.
      if (!uvs) {
        EXPECT_EQ(m.plain_vertices, m.plain_triangles / 2 + 2);
      }
    }
  }
}

// --- error ----------------------------------------------------------------------------

// Sub-face k of a Catmull-Clark triangle and its (s,t) at barycentric point w: the
// inverse of the bilinear map through corner k, the midpoint of edge k, the centroid and
// the midpoint of edge k-1. With x = w[k+1], y = w[k-1] the map is x = s (3 - t) / 6,
// y = t (3 - s) / 6; eliminating s gives t^2 - (3 + 2y - 2x) t + 6y = 0, smaller root.
ref::SubFacePoint invertSubFaceMap(const techniques::DomainCoord& w) {
  int k = 0;
  for (int c = 1; c < 3; ++c) {
    if (w[c] > w[k]) k = c;
  }
  const double x = w[(k + 1) % 3], y = w[(k + 2) % 3];
  const double b = 3 + 2 * y - 2 * x;
  const double t = 12 * y / (b + std::sqrt(b * b - 24 * y));
  return {k, {6 * x / (3 - t), t}};
}

// The exact Catmull-Clark limit, optionally offset: quads at their face (u,v), triangles
// at the face (u,v) of invertSubFaceMap's sub-face point.
class ExactLimitPatches final : public MixedPatches {
 public:
  ExactLimitPatches(mesh::Mesh mesh, mesh::Vec3d offset)
      : MixedPatches(std::move(mesh)), limit_(mesh_, osd::Scheme::kCatmullClark), offset_(offset) {}
  techniques::SurfacePoint evaluate(size_t patch, const techniques::DomainCoord& c) const override {
    mesh::Vec2d uv{c[0], c[1]};
    if (patchDomain(patch) == techniques::PatchDomain::kTriangle) {
      const ref::SubFacePoint sub = invertSubFaceMap(c);
      uv = ref::subFaceToFaceUv(osd::Scheme::kCatmullClark, 3, sub.sub_face, sub.st);
    }
    const ref::LimitPoint point = limit_.evaluate(patch, uv.x, uv.y);
    return {point.position + offset_, point.normal};
  }
  techniques::SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& c) const override {
    const techniques::SurfacePoint point = evaluate(patch, {c[0], c[1], c[2]});
    return {vecCast<float>(point.position), vecCast<float>(point.normal)};
  }

 private:
  ref::LimitSurface limit_;
  mesh::Vec3d offset_;
};

TEST(MixedDomains, TheCatmullClarkLimitThroughTheSubFaceMapHasNoParametricError) {
  for (const char* asset : {"opensubdiv/catmark_pyramid.obj", "opensubdiv/loop_icosahedron.obj"}) {
    SCOPED_TRACE(asset);
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(asset));
    const ExactLimitPatches patches(mesh, {0, 0, 0});
    const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
    const measures::SurfaceErrorFigures f = measures::measureSurfaceError(patches, limit);
    size_t triangles = 0, quads = 0;
    for (size_t p = 0; p < patches.patchCount(); ++p) {
      (patches.patchDomain(p) == techniques::PatchDomain::kQuad ? quads : triangles) += 1;
    }
    EXPECT_EQ(f.patches_through_sub_faces, triangles);
    EXPECT_EQ(f.samples, triangles * 3 * 25 + quads * 81);
    EXPECT_LT(f.parametric_max, 1e-12);
    // acos near 1 resolves about 1e-6 degrees (acos(1 - 2^-52) = 1.2e-6 deg).
    EXPECT_LT(f.normal_max_deg, 1e-5);
    EXPECT_LT(f.hausdorff, 2e-3);  // the chords of the two tessellations
  }
}

TEST(MixedDomains, AnOffsetAndFlatPatchesAreMeasuredOnMixedPatches) {
  const mesh::Mesh mesh = pyramid();
  const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
  const double offset = 0.01;
  const measures::SurfaceErrorFigures shifted =
      measures::measureSurfaceError(ExactLimitPatches(mesh, {0, 0, offset}), limit);
  EXPECT_NEAR(shifted.parametric_max * shifted.bbox_diagonal, offset, 1e-12);
  EXPECT_NEAR(shifted.parametric_rms * shifted.bbox_diagonal, offset, 1e-12);
  // The control pyramid is far outside its shrunken limit surface.
  const measures::SurfaceErrorFigures flat =
      measures::measureSurfaceError(FlatMixedPatches(mesh, false), limit);
  EXPECT_GT(flat.parametric_max, 1e-2);
  EXPECT_GT(flat.hausdorff, 1e-2);
}

TEST(MixedDomains, TheSchemeComesFromApproximatesAndMismatchesThrow) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/loop_icosahedron.obj"));
  const ExactLimitPatches patches(mesh, {0, 0, 0});  // triangles approximating Catmull-Clark
  const ref::LimitSurface loop(mesh, osd::Scheme::kLoop);
  EXPECT_THROW(measures::measureSurfaceError(patches, loop), std::logic_error);

  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  const measures::Measure* measure = measures::MeasureRegistry::instance().find("error");
  ASSERT_NE(measure, nullptr);
  const techniques::VariantInfo variant = phong->variants()[0];
  const results::MeasureResult result =
      measure->run({*phong, variant, "loop_icosahedron", mesh, &patches, nullptr, "none"});
  ASSERT_EQ(result.rows.size(), 1u);
  EXPECT_EQ(result.rows[0].keys.at("reference"), "catmull_clark_limit");
  bool sub_face_note = false;
  for (const std::string& note : result.notes) {
    sub_face_note |= note.find("sub-faces") != std::string::npos;
  }
  EXPECT_TRUE(sub_face_note);
}

// --- instructions ---------------------------------------------------------------------

// Operation counts that tell the domains apart, and one (static-count only) program each.
class ProfiledMixedPatches final : public MixedPatches {
 public:
  using MixedPatches::MixedPatches;
  techniques::SurfacePoint evaluate(size_t, const techniques::DomainCoord&) const override {
    return {};
  }
  techniques::SurfacePointF evaluateFloat(size_t, const tess::DomainPoint&) const override {
    return {};
  }
  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override {
    gpu::GpuPatchProgram quads, triangles;
    quads.control_shader = "gpu/test_bilinear.tesc";
    quads.evaluation_shader = "gpu/test_bilinear.tese";
    quads.specialization = {std::bit_cast<uint32_t>(1.0f)};
    triangles.control_shader = "gpu/tess_levels.tesc";
    triangles.evaluation_shader = "gpu/tess_capture.tese";
    triangles.domain = tess::Domain::kTriangle;
    return {quads, triangles};
  }
  std::optional<techniques::OperationProfile> operationProfile(size_t patch) const override {
    techniques::OperationProfile profile;
    // Quads 100 multiplies; triangle p: 10 + p.
    profile.per_vertex.mul =
        patchDomain(patch) == techniques::PatchDomain::kQuad ? 100 : 10 + patch;
    return profile;
  }
};

TEST(MixedDomains, InstructionRowsAreKeyedByProgramDomain) {
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  const measures::Measure* measure = measures::MeasureRegistry::instance().find("instructions");
  const mesh::Mesh mesh = pyramid();
  const ProfiledMixedPatches patches(mesh);
  const techniques::VariantInfo variant = phong->variants()[0];
  const results::MeasureResult result =
      measure->run({*phong, variant, "catmark_pyramid", mesh, &patches, nullptr, "none"});
  std::map<std::string, int> static_rows;
  std::map<std::string, double> mul;
  for (const results::MetricRow& row : result.rows) {
    ASSERT_TRUE(row.keys.contains("program"));
    const std::string key = row.keys.at("program") + " " + row.keys.at("stage");
    if (row.keys.at("source") == "spirv_O") {
      EXPECT_EQ(row.status, results::MeasureStatus::kOk) << row.reason;
      ++static_rows[key];
    } else if (row.keys.at("stage") == "per_vertex") {
      for (const results::Metric& m : row.metrics) {
        if (m.name == "mul") mul[row.keys.at("program") + " " + row.keys.at("patch")] = m.value;
      }
    }
  }
  const std::map<std::string, int> expected_static = {{"quad gpu/test_bilinear.tesc", 2},
                                                      {"quad gpu/test_bilinear.tese", 2},
                                                      {"triangle gpu/tess_levels.tesc", 2},
                                                      {"triangle gpu/tess_capture.tese", 2}};
  EXPECT_EQ(static_rows, expected_static);
  const std::map<std::string, double> expected_mul = {{"quad min (patch 4)", 100},
                                                      {"quad max (patch 4)", 100},
                                                      {"triangle min (patch 0)", 10},
                                                      {"triangle max (patch 3)", 13}};
  EXPECT_EQ(mul, expected_mul);
}

// --- GPU: several programs ------------------------------------------------------------

// A quad grid split over two programs of the bilinear test shaders (even and odd
// patches, GpuPatchProgram::patch_ids) must capture what one program over all does.
class SplitQuadPatches final : public MixedPatches {
 public:
  SplitQuadPatches(mesh::Mesh mesh, bool split) : MixedPatches(std::move(mesh)), split_(split) {}
  techniques::SurfacePoint evaluate(size_t patch, const techniques::DomainCoord& c) const override {
    const techniques::SurfacePointF f =
        evaluateFloat(patch, {float(c[0]), float(c[1]), float(c[2])});
    return {vecCast<double>(f.position), {0, 0, 1}};
  }
  techniques::SurfacePointF evaluateFloat(size_t patch, const tess::DomainPoint& c) const override {
    // shaders/gpu/test_bilinear.tese with scale 1
    const mesh::Vec3f p0 = cornerF(patch, 0), p1 = cornerF(patch, 1), p2 = cornerF(patch, 2),
                      p3 = cornerF(patch, 3);
    const float u = c[0], v = c[1];
    const mesh::Vec3f bottom = p0 * (1 - u) + p1 * u, top = p3 * (1 - u) + p2 * u;
    return {(bottom * (1 - v) + top * v) * 1.0f, {0, 0, 1}};
  }
  std::vector<gpu::GpuPatchProgram> gpuPrograms() const override {
    std::vector<gpu::GpuPatchProgram> programs;
    for (uint32_t parity = 0; parity < (split_ ? 2u : 1u); ++parity) {
      gpu::GpuPatchProgram program;
      program.control_shader = "gpu/test_bilinear.tesc";
      program.evaluation_shader = "gpu/test_bilinear.tese";
      program.specialization = {std::bit_cast<uint32_t>(1.0f)};
      std::vector<uint32_t> corners;
      for (uint32_t p = 0; p < patchCount(); ++p) {
        if (split_ && p % 2 != parity) continue;
        if (split_) program.patch_ids.push_back(p);
        for (uint32_t k = 0; k < 4; ++k) {
          const mesh::Vec3f c = cornerF(p, k);
          for (float x : {c.x, c.y, c.z, 1.0f}) corners.push_back(std::bit_cast<uint32_t>(x));
        }
      }
      program.patch_count = uint32_t(corners.size() / 16);
      program.storage_buffers = {corners};
      programs.push_back(std::move(program));
    }
    return programs;
  }

 private:
  bool split_;
};

mesh::Mesh quadGrid(int cells) {
  std::string obj;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      obj += "v " + std::to_string(i * 0.7310585) + " " + std::to_string(j * 0.6224593) + " " +
             std::to_string(0.3 * std::sin(i + 2.0 * j)) + "\n";
    }
  }
  auto id = [&](int i, int j) { return std::to_string(j * (cells + 1) + i + 1); };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      obj +=
          "f " + id(i, j) + " " + id(i + 1, j) + " " + id(i + 1, j + 1) + " " + id(i, j + 1) + "\n";
    }
  }
  return mesh::loadObjText(obj, "quad_grid.obj");
}

TEST(MixedDomains, TwoGpuProgramsCaptureWhatOneDoes) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const SplitQuadPatches one(quadGrid(3), false), two(quadGrid(3), true);
  ASSERT_EQ(two.gpuPrograms().size(), 2u);
  for (float level : {1.0f, 7.3f}) {
    const measures::CrackFigures a = measures::measureCracks(
        one, tess::Spacing::kFractionalOdd, level, measures::CrackBackend::kGpu, &context);
    const measures::CrackFigures b = measures::measureCracks(
        two, tess::Spacing::kFractionalOdd, level, measures::CrackBackend::kGpu, &context);
    ASSERT_TRUE(a.measured && b.measured) << a.skipped_reason << b.skipped_reason;
    EXPECT_EQ(b.device_points, a.device_points);
    EXPECT_EQ(b.device_points_differing, 0u);
    EXPECT_EQ(b.points_compared, a.points_compared);
    EXPECT_GT(b.points_compared, 0u);
    EXPECT_EQ(b.points_not_equal, a.points_not_equal);
  }
}

}  // namespace
}  // namespace tb
