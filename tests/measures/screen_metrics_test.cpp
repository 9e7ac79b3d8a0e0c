// Oracles: geometry by hand (a flat patch is its own tessellation; a square facing the
// camera has edges of a length computed from the projection), the chord's sagitta (error
// falls as 1/n^2 with the level n), the Catmull-Clark limit itself (acc is exactly the
// bicubic B-spline limit on regular faces), and the serial run (thread invariance).
#include "harness/lod/screen_metrics.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/mesh/obj_loader.h"
#include "core/view/camera.h"
#include "harness/measures/error/error.h"
#include "harness/suite/camera_path.h"
#include "reference/limit_surface.h"
#include "techniques/registry.h"
#include "tests/measures/face_patches.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr double kFovYRad = 60 * std::numbers::pi / 180;

view::View makeView(const mesh::Vec3d& eye, const mesh::Vec3d& target, uint32_t width_px,
                    uint32_t height_px, double near_plane, double far_plane) {
  return view::perspectiveView({.eye = eye,
                                .target = target,
                                .fov_y_rad = kFovYRad,
                                .width_px = width_px,
                                .height_px = height_px,
                                .near_plane = near_plane,
                                .far_plane = far_plane});
}

// A 1920 x 1080 view of the mesh's bounding sphere from above and aside, the sphere's
// diameter about half the screen height (2 r f / d = 1/2 of NDC's height of 2).
view::View halfScreenView(const mesh::Mesh& mesh) {
  const mesh::Aabb box = mesh::boundsOf(mesh);
  const mesh::Vec3d centre = 0.5 * (box.min + box.max);
  const double radius = 0.5 * length(box.max - box.min);
  const double distance = 2 * radius / std::tan(kFovYRad / 2);
  const mesh::Vec3d eye = centre + distance * normalize(mesh::Vec3d{0.6, 0.5, 0.8});
  return makeView(eye, centre, 1920, 1080, distance - 1.5 * radius, distance + 1.5 * radius);
}

tess::Levels uniformLevels(float level) { return {{level, level, level, level}, {level, level}}; }

std::vector<tess::Levels> uniform(const techniques::SurfacePatches& patches, float level) {
  return std::vector<tess::Levels>(patches.patchCount(), uniformLevels(level));
}

techniques::BuiltSurface build(const std::string& technique, const mesh::Mesh& mesh) {
  const techniques::Technique* t = techniques::TechniqueRegistry::instance().find(technique);
  return techniques::buildSurface(*t, mesh, t->variants()[0]);
}

mesh::Mesh asset(const std::string& name) { return mesh::loadObjFile(testing::assetPath(name)); }

// The bundled pawn without its crease tags, which acc refuses (a smooth Catmull-Clark
// mesh with extraordinary vertices and boundaries).
mesh::Mesh smoothPawn() {
  mesh::Mesh mesh = asset("opensubdiv/catmark_pawn.obj");
  mesh.tags.creases.clear();
  mesh.tags.corners.clear();
  return mesh;
}

// Test double: patch p is face p, flat: the bilinear interpolation of a quad's corners,
// the barycentric one of a triangle's. Graded against Catmull-Clark.
class FlatFaces final : public testing::FacePatches {
 public:
  using FacePatches::FacePatches;
  techniques::LimitScheme approximates() const override {
    return techniques::LimitScheme::kCatmullClark;
  }
  techniques::SurfacePoint evaluate(size_t p, const techniques::DomainCoord& c) const override {
    const auto f = mesh_.facePositions(p);
    const auto& x = mesh_.positions;
    if (f.size() == 3) return {c[0] * x[f[0]] + c[1] * x[f[1]] + c[2] * x[f[2]], {0, 0, 1}};
    const double u = c[0], v = c[1];
    return {(1 - u) * (1 - v) * x[f[0]] + u * (1 - v) * x[f[1]] + u * v * x[f[2]] +
                (1 - u) * v * x[f[3]],
            {0, 0, 1}};
  }
  techniques::SurfacePointF evaluateFloat(size_t p, const tess::DomainPoint& c) const override {
    const techniques::SurfacePoint point = evaluate(p, {c[0], c[1], c[2]});
    return {vecCast<float>(point.position), vecCast<float>(point.normal)};
  }
};

// Test double: the exact Loop limit of each face, at the parameter error.cpp maps a
// triangle patch's barycentric (u, v, w) to: Bfr's (u, v) = (v, w).
class LoopLimitPatches final : public testing::FacePatches {
 public:
  explicit LoopLimitPatches(const mesh::Mesh& mesh)
      : FacePatches(mesh), limit_(mesh, osd::Scheme::kLoop) {}
  techniques::SurfacePoint evaluate(size_t p, const techniques::DomainCoord& c) const override {
    const ref::LimitPoint point = limit_.evaluate(p, c[1], c[2]);
    return {point.position, point.normal};
  }
  techniques::SurfacePointF evaluateFloat(size_t p, const tess::DomainPoint& c) const override {
    const techniques::SurfacePoint point = evaluate(p, {c[0], c[1], c[2]});
    return {vecCast<float>(point.position), vecCast<float>(point.normal)};
  }

 private:
  ref::LimitSurface limit_;
};

// A 3 x 2 grid of unit squares in the plane z = 0.3, each split into two triangles.
constexpr const char* kFlatTriangles = R"(v 0 0 0.3
v 1 0 0.3
v 2 0 0.3
v 3 0 0.3
v 0 1 0.3
v 1 1 0.3
v 2 1 0.3
v 3 1 0.3
v 0 2 0.3
v 1 2 0.3
v 2 2 0.3
v 3 2 0.3
f 1 2 6
f 1 6 5
f 2 3 7
f 2 7 6
f 3 4 8
f 3 8 7
f 5 6 10
f 5 10 9
f 6 7 11
f 6 11 10
f 7 8 12
f 7 12 11
)";

TEST(ScreenMetrics, AFlatSurfaceHasNoTessellationError) {
  // Phong and PN triangles reproduce a plane with flat normals affinely in the
  // barycentric coordinates, so the tessellation is the surface (1e-9 px: rounding).
  const mesh::Mesh mesh = mesh::loadObjText(kFlatTriangles, "flat.obj");
  const view::View view = makeView({1.5, -2, 3}, {1.5, 1, 0.3}, 1920, 1080, 0.5, 20);
  for (const char* technique : {"phong", "pn_triangles"}) {
    const techniques::BuiltSurface patches = build(technique, mesh);
    lod::ScreenMetrics metrics(*patches, nullptr);
    for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kFractionalOdd}) {
      for (float level : {1.0f, 3.0f, 6.5f, 17.0f}) {
        const lod::ScreenErrorFigures f =
            metrics.frame(spacing, uniform(*patches, level), view).tessellation_error;
        EXPECT_GT(f.samples, 0u) << technique << " level " << level;
        EXPECT_LE(f.max_px, 1e-9) << technique << " level " << level;
      }
    }
  }
}

TEST(ScreenMetrics, TessellationErrorFallsWithTheSquareOfTheLevel) {
  // The chord error of a smooth surface is its sagitta, ~ curvature * (edge length)^2 / 8:
  // doubling the level quarters it. 0.15..0.40 allows for the projection and the
  // boundaries of the sampled regions.
  const mesh::Mesh mesh = asset("opensubdiv/catmark_torus.obj");
  const techniques::BuiltSurface patches = build("acc", mesh);
  lod::ScreenMetrics metrics(*patches, nullptr);
  const view::View view = halfScreenView(mesh);
  double previous_max = 0, previous_rms = 0;
  for (float level : {2.0f, 4.0f, 8.0f, 16.0f}) {
    const lod::ScreenErrorFigures f =
        metrics.tessellationError(tess::Spacing::kInteger, uniform(*patches, level), view);
    ASSERT_GT(f.samples, 0u);
    EXPECT_GT(f.max_px, 0.0);
    if (previous_max > 0) {
      EXPECT_GT(f.max_px / previous_max, 0.15) << "level " << level;
      EXPECT_LT(f.max_px / previous_max, 0.40) << "level " << level;
      EXPECT_GT(f.rms_px / previous_rms, 0.15) << "level " << level;
      EXPECT_LT(f.rms_px / previous_rms, 0.40) << "level " << level;
    }
    previous_max = f.max_px;
    previous_rms = f.rms_px;
  }
}

TEST(ScreenMetrics, EdgesOfASquareFacingTheCameraHaveTheLengthComputedByHand) {
  // A unit square centred on the view axis at distance d: every point has clip w = d, so
  // an edge of 1/n world units spans (1/n) * projection_y_scale / d of NDC's height of 2,
  // i.e. (1/n) * H * projection_y_scale / (2 d) pixels. Of the 2n(n+1) axis-parallel
  // edges and n^2 diagonals (sqrt(2) longer), the axis-parallel ones are the majority.
  // Powers of two, so that 1/n is exact in the tessellator's 16.16 fixed point.
  const mesh::Mesh mesh = mesh::loadObjText(
      "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3 4\n", "square.obj");
  const FlatFaces patches(mesh);
  const double distance = 3;
  const view::View view = makeView({0, 0, distance}, {0, 0, 0}, 800, 600, 1, 10);
  lod::ScreenMetrics metrics(patches, nullptr);
  for (uint32_t n : {1u, 4u, 8u}) {
    const lod::FrameScreenFigures f =
        metrics.frame(tess::Spacing::kInteger, uniform(patches, float(n)), view);
    const double expected_px = 1.0 / n * 600 * view.projection_y_scale / (2 * distance);
    EXPECT_EQ(f.patches, 1u);
    EXPECT_EQ(f.triangles, 2 * n * n);
    EXPECT_EQ(f.domain_points, (n + 1) * (n + 1));
    EXPECT_EQ(f.edges.edges, 2 * n * (n + 1) + n * n);
    EXPECT_NEAR(f.edges.median_px, expected_px, 1e-6) << "n " << n;
    EXPECT_NEAR(f.edges.p05_px, expected_px, 1e-6) << "n " << n;
    EXPECT_NEAR(f.edges.p95_px, std::sqrt(2.0) * expected_px, 1e-6) << "n " << n;
    // In band [4, 16] px: the axis edges at n = 4 (~21.6 / 4 = 5.4 px) and the diagonals.
    const bool axis_in = expected_px >= 4 && expected_px <= 16;
    const bool diagonal_in =
        std::sqrt(2.0) * expected_px >= 4 && std::sqrt(2.0) * expected_px <= 16;
    const double expected_fraction =
        (axis_in * 2.0 * n * (n + 1) + diagonal_in * double(n * n)) / double(f.edges.edges);
    EXPECT_DOUBLE_EQ(f.edges.fraction_in_band, expected_fraction) << "n " << n;
    EXPECT_LE(f.tessellation_error.max_px, 1e-9);  // a parallelogram is affine in (u, v)
  }
}

TEST(ScreenMetrics, NothingIsVisibleBehindTheCameraOrOutsideTheViewport) {
  const mesh::Mesh mesh = mesh::loadObjText(
      "v -0.5 -0.5 0\nv 0.5 -0.5 0\nv 0.5 0.5 0\nv -0.5 0.5 0\nf 1 2 3 4\n", "square.obj");
  const FlatFaces patches(mesh);
  lod::ScreenMetrics metrics(patches, nullptr);
  const std::vector<tess::Levels> levels = uniform(patches, 4);
  // Looking away from the square, then at it from beside, far out of the field of view.
  for (const view::View& view : {makeView({0, 0, 3}, {0, 0, 6}, 800, 600, 1, 10),
                                 makeView({20, 0, 3}, {20, 0, 0}, 800, 600, 1, 10)}) {
    const lod::FrameScreenFigures f = metrics.frame(tess::Spacing::kInteger, levels, view);
    EXPECT_EQ(f.patches, 1u);
    EXPECT_EQ(f.edges.edges, 0u);
    EXPECT_EQ(f.tessellation_error.samples, 0u);
    EXPECT_EQ(f.edges.median_px, 0.0);
  }
}

TEST(ScreenMetrics, CulledPatchesContributeNothing) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_torus.obj");
  const techniques::BuiltSurface patches = build("acc", mesh);
  lod::ScreenMetrics metrics(*patches, nullptr);
  const view::View view = halfScreenView(mesh);
  std::vector<tess::Levels> levels = uniform(*patches, 5);
  const lod::FrameScreenFigures all = metrics.frame(tess::Spacing::kInteger, levels, view);
  levels[3].outer[1] = 0;  // culls patch 3
  const lod::FrameScreenFigures culled = metrics.frame(tess::Spacing::kInteger, levels, view);
  EXPECT_EQ(culled.patches, all.patches - 1);
  EXPECT_EQ(culled.triangles, all.triangles - 50);
  EXPECT_EQ(culled.domain_points, all.domain_points - 36);
  EXPECT_LT(culled.edges.edges, all.edges.edges);
  EXPECT_THROW(metrics.frame(tess::Spacing::kInteger, std::span(levels).first(5), view),
               std::invalid_argument);
}

TEST(ScreenMetrics, EachPatchAloneAddsUpToTheWholeSurface) {
  // Distinct high levels per patch split the torus into several chunks of patterns; each
  // patch measured alone (every other patch culled) must give the same samples and max.
  const mesh::Mesh mesh = asset("opensubdiv/catmark_torus.obj");
  const techniques::BuiltSurface patches = build("acc", mesh);
  lod::ScreenMetrics metrics(*patches, nullptr);
  const view::View view = halfScreenView(mesh);
  std::vector<tess::Levels> levels;
  for (size_t p = 0; p < patches->patchCount(); ++p) levels.push_back(uniformLevels(40.0f + p));
  const lod::ScreenErrorFigures whole =
      metrics.tessellationError(tess::Spacing::kFractionalEven, levels, view);
  uint64_t samples = 0;
  double max_px = 0, squares = 0;
  for (size_t p = 0; p < patches->patchCount(); ++p) {
    std::vector<tess::Levels> alone(levels.size(), tess::Levels{{0, 0, 0, 0}, {0, 0}});
    alone[p] = levels[p];
    const lod::ScreenErrorFigures f =
        metrics.tessellationError(tess::Spacing::kFractionalEven, alone, view);
    samples += f.samples;
    max_px = std::max(max_px, f.max_px);
    squares += f.rms_px * f.rms_px * double(f.samples);
  }
  EXPECT_EQ(whole.samples, samples);
  // The whole surface (every patch its own levels) evaluates point by point, a patch alone
  // (the rest culled: two patterns for every patch) with the technique's batch kernel;
  // the two agree to rounding.
  EXPECT_NEAR(whole.max_px, max_px, 1e-9 * max_px);
  EXPECT_NEAR(whole.rms_px, std::sqrt(squares / double(samples)), 1e-12 * whole.rms_px);
}

TEST(ScreenMetrics, PopIsZeroForUnchangedLevelsAndSmallForAFractionalStep) {
  // Integer spacing moves every vertex when the level steps from 3 to 4; fractional_odd
  // from 3.0 to 3.2 only slides the new vertex pair out of the old ones.
  const mesh::Mesh mesh = asset("opensubdiv/catmark_torus.obj");
  const techniques::BuiltSurface patches = build("acc", mesh);
  lod::ScreenMetrics metrics(*patches, nullptr);
  const view::View view = halfScreenView(mesh);
  const lod::ScreenErrorFigures same =
      metrics.pop(tess::Spacing::kInteger, uniform(*patches, 3), uniform(*patches, 3), view);
  EXPECT_GT(same.samples, 0u);
  EXPECT_EQ(same.max_px, 0.0);
  const lod::ScreenErrorFigures integer =
      metrics.pop(tess::Spacing::kInteger, uniform(*patches, 3), uniform(*patches, 4), view);
  const lod::ScreenErrorFigures fractional = metrics.pop(
      tess::Spacing::kFractionalOdd, uniform(*patches, 3.0f), uniform(*patches, 3.2f), view);
  EXPECT_EQ(integer.samples, same.samples);
  EXPECT_GT(fractional.max_px, 0.0);
  EXPECT_GT(integer.max_px, fractional.max_px);
  EXPECT_GT(integer.rms_px, fractional.rms_px);
}

// Per-patch levels that vary, with one culled patch and fractional values.
std::vector<tess::Levels> mixedLevels(const techniques::SurfacePatches& patches, float shift) {
  std::vector<tess::Levels> levels;
  for (size_t p = 0; p < patches.patchCount(); ++p) {
    const float base = 1.5f + float(p % 7) + shift;
    levels.push_back({{base, base + 1, base + 0.25f, base + 2}, {base + 0.5f, base}});
  }
  levels[1].outer = {0, 0, 0, 0};
  return levels;
}

void expectEqual(const lod::ScreenErrorFigures& a, const lod::ScreenErrorFigures& b) {
  EXPECT_EQ(a.samples, b.samples);
  EXPECT_EQ(a.max_px, b.max_px);
  EXPECT_EQ(a.rms_px, b.rms_px);
}

TEST(ScreenMetrics, FiguresDoNotDependOnTheThreadCount) {
  const mesh::Mesh mesh = smoothPawn();
  const techniques::BuiltSurface patches = build("acc", mesh);
  const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
  const view::View view = halfScreenView(mesh);
  const std::vector<tess::Levels> before = mixedLevels(*patches, 0),
                                  after = mixedLevels(*patches, 0.3f);
  auto run = [&](lod::FrameScreenFigures* frame, lod::ScreenErrorFigures* error,
                 lod::ScreenErrorFigures* pop) {
    lod::ScreenMetrics metrics(*patches, &limit);
    *frame = metrics.frame(tess::Spacing::kFractionalEven, before, view);
    *error = metrics.tessellationError(tess::Spacing::kFractionalEven, after, view);
    *pop = metrics.pop(tess::Spacing::kFractionalEven, before, after, view);
  };
  lod::FrameScreenFigures frame_1, frame_n;
  lod::ScreenErrorFigures error_1, error_n, pop_1, pop_n;
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    run(&frame_1, &error_1, &pop_1);
  }
  run(&frame_n, &error_n, &pop_n);
  EXPECT_GT(frame_n.edges.edges, 0u);
  EXPECT_GT(frame_n.reference_error.samples, 0u);
  EXPECT_GT(pop_n.samples, 0u);
  EXPECT_EQ(frame_1.patches, frame_n.patches);
  EXPECT_EQ(frame_1.triangles, frame_n.triangles);
  EXPECT_EQ(frame_1.domain_points, frame_n.domain_points);
  EXPECT_EQ(frame_1.edges.edges, frame_n.edges.edges);
  EXPECT_EQ(frame_1.edges.median_px, frame_n.edges.median_px);
  EXPECT_EQ(frame_1.edges.p05_px, frame_n.edges.p05_px);
  EXPECT_EQ(frame_1.edges.p95_px, frame_n.edges.p95_px);
  EXPECT_EQ(frame_1.edges.fraction_in_band, frame_n.edges.fraction_in_band);
  expectEqual(frame_1.tessellation_error, frame_n.tessellation_error);
  expectEqual(frame_1.reference_error, frame_n.reference_error);
  expectEqual(error_1, error_n);
  expectEqual(pop_1, pop_n);
}

TEST(ScreenMetrics, CachedPatternsDoNotChangeTheFigures) {
  // A pattern first built for pop (vertices and lattice only) gains its samples later; the
  // figures must equal those of a fresh object with an empty cache.
  const mesh::Mesh mesh = smoothPawn();
  const techniques::BuiltSurface patches = build("acc", mesh);
  const view::View view = halfScreenView(mesh);
  const std::vector<tess::Levels> before = mixedLevels(*patches, 0),
                                  after = mixedLevels(*patches, 1);
  lod::ScreenMetrics used(*patches, nullptr), fresh(*patches, nullptr);
  EXPECT_GT(used.pop(tess::Spacing::kFractionalOdd, before, after, view).samples, 0u);
  const lod::FrameScreenFigures a = used.frame(tess::Spacing::kFractionalOdd, after, view);
  const lod::FrameScreenFigures b = fresh.frame(tess::Spacing::kFractionalOdd, after, view);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.edges.edges, b.edges.edges);
  EXPECT_EQ(a.edges.median_px, b.edges.median_px);
  expectEqual(a.tessellation_error, b.tessellation_error);
  expectEqual(used.pop(tess::Spacing::kFractionalOdd, before, after, view),
              fresh.pop(tess::Spacing::kFractionalOdd, before, after, view));
}

TEST(ScreenMetrics, AccMatchesTheLimitOnARegularMeshOnly) {
  // On the all-valence-4 torus every acc patch is the bicubic B-spline patch that is the
  // Catmull-Clark limit (Bfr, the oracle): ~0 px. The cube's valence-3 corners are not.
  for (const auto& [name, regular] :
       {std::pair{"opensubdiv/catmark_torus.obj", true}, {"opensubdiv/catmark_cube.obj", false}}) {
    const mesh::Mesh mesh = asset(name);
    const techniques::BuiltSurface patches = build("acc", mesh);
    const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
    lod::ScreenMetrics metrics(*patches, &limit);
    const lod::FrameScreenFigures f =
        metrics.frame(tess::Spacing::kInteger, uniform(*patches, 6), halfScreenView(mesh));
    EXPECT_TRUE(f.reference_measured);
    EXPECT_EQ(f.patches_without_reference, 0u);
    EXPECT_GT(f.reference_error.samples, 0u) << name;
    if (regular) {
      EXPECT_LE(f.reference_error.max_px, 1e-6) << name;
    } else {
      EXPECT_GT(f.reference_error.max_px, 1.0) << name;
    }
  }
}

TEST(ScreenMetrics, TheLoopLimitItselfHasNoReferenceError) {
  // Oracle: Bfr against itself, so only a wrong parameter map gives an error.
  const mesh::Mesh mesh = asset("opensubdiv/loop_icosahedron.obj");
  const LoopLimitPatches patches(mesh);
  const ref::LimitSurface limit(mesh, osd::Scheme::kLoop);
  lod::ScreenMetrics metrics(patches, &limit);
  const lod::FrameScreenFigures f =
      metrics.frame(tess::Spacing::kFractionalOdd, uniform(patches, 4.5f), halfScreenView(mesh));
  EXPECT_EQ(f.patches_without_reference, 0u);
  EXPECT_GT(f.reference_error.samples, 0u);
  EXPECT_LE(f.reference_error.max_px, 1e-9);
  EXPECT_GT(f.tessellation_error.max_px, 0.01);  // the limit is curved
}

TEST(ScreenMetrics, TrianglesOnACatmullClarkMeshAreLeftOutOfTheReference) {
  // The pyramid's four triangles are split into quad sub-faces by Catmull-Clark; its
  // square base is a quad patch on a quad face and is measured.
  const mesh::Mesh mesh = asset("opensubdiv/catmark_pyramid.obj");
  const FlatFaces patches(mesh);
  const ref::LimitSurface limit(mesh, osd::Scheme::kCatmullClark);
  lod::ScreenMetrics metrics(patches, &limit);
  const lod::FrameScreenFigures f =
      metrics.frame(tess::Spacing::kInteger, uniform(patches, 4), halfScreenView(mesh));
  EXPECT_EQ(f.patches, 5u);
  EXPECT_EQ(f.patches_without_reference, 4u);
  EXPECT_EQ(f.reference_error.samples, 25u);  // the base's 5 x 5 vertices
  EXPECT_GT(f.reference_error.max_px, 1.0);   // flat faces are not the limit
  EXPECT_LE(f.tessellation_error.max_px, 1e-9);
}

TEST(ScreenMetrics, ALimitOfAnotherSchemeIsRefused) {
  const mesh::Mesh mesh = asset("opensubdiv/catmark_torus.obj");
  const techniques::BuiltSurface patches = build("acc", mesh);
  const mesh::Mesh loop_mesh = asset("opensubdiv/loop_icosahedron.obj");
  const ref::LimitSurface loop(loop_mesh, osd::Scheme::kLoop);
  EXPECT_THROW(lod::ScreenMetrics(*patches, &loop), std::logic_error);
}

}  // namespace
}  // namespace tb
