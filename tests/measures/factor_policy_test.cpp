// Factor policies (harness/lod/factor_policy.h) against hand-computed factors, and
// their CPU twin against the levels every technique's own TCS writes on the device
// (shaders/common/tess_factors.glsl), bit for bit.
#include "harness/lod/factor_policy.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>

#include "core/gpu/patch_program.h"
#include "core/mesh/obj_loader.h"
#include "core/view/camera.h"
#include "harness/measures/common/cracks/cracks.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr double kPi = std::numbers::pi;

view::View viewFrom(const mesh::Vec3d& eye, const mesh::Vec3d& target, double fov_y_deg,
                    uint32_t width, uint32_t height, double near_plane, double far_plane) {
  return view::perspectiveView({.eye = eye,
                                .target = target,
                                .fov_y_rad = fov_y_deg * kPi / 180,
                                .width_px = width,
                                .height_px = height,
                                .near_plane = near_plane,
                                .far_plane = far_plane});
}

// A few views around `bounds`: near, far, grazing, so factors span the clamp range.
std::vector<view::View> viewsAround(const mesh::Aabb& bounds) {
  const mesh::Vec3d centre = 0.5 * (bounds.min + bounds.max);
  const double diagonal = length(bounds.max - bounds.min);
  std::vector<view::View> views;
  const double distances[] = {0.4, 1.0, 3.0, 12.0};
  for (size_t i = 0; i < std::size(distances); ++i) {
    const double azimuth = 0.7 + 1.9 * double(i), elevation = 0.3 - 0.2 * double(i);
    const mesh::Vec3d direction{std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                std::cos(elevation) * std::cos(azimuth)};
    views.push_back(viewFrom(centre + distances[i] * diagonal * direction, centre, 45, 1920, 1080,
                             0.01 * diagonal, 100 * diagonal));
  }
  return views;
}

TEST(FactorPolicy, NamesRoundTrip) {
  for (const char* name :
       {"uniform", "distance", "sphere_diameter", "lp2_edge", "lp2_edge_silhouette",
        "lp2_edge_roundness", "sphere_diameter_order_dependent", "lp2_edge_order_dependent"}) {
    const std::optional<lod::FactorPolicy> policy = lod::parseFactorPolicy(name);
    ASSERT_TRUE(policy.has_value()) << name;
    EXPECT_EQ(policy->name(), name);
  }
  EXPECT_FALSE(lod::parseFactorPolicy("sphere").has_value());
  EXPECT_FALSE(lod::parseFactorPolicy("_order_dependent").has_value());
}

// The flat unit quad facing the camera at distance 4 (45 degree field of view, 1080 px
// high), sphere_diameter at 8 px per edge: each edge's factor is by hand
// d * P11 / w * H / (2 * 8) = 1 * (1 / tan(22.5 deg)) / 4 * 1080 / 16 = 40.7386...
// (w = 4: every edge midpoint lies in the plane z = 0, 4 in front of the eye).
struct FacingQuad {
  view::View view = viewFrom({0, 0, 4}, {0, 0, 0}, 45, 1920, 1080, 0.1, 100);
  std::array<lod::FactorCorner, 4> corners{{{{-0.5f, -0.5f, 0}, {0, 0, 1}},
                                            {{0.5f, -0.5f, 0}, {0, 0, 1}},
                                            {{0.5f, 0.5f, 0}, {0, 0, 1}},
                                            {{-0.5f, 0.5f, 0}, {0, 0, 1}}}};
  static double handFactor() { return 1.0 / std::tan(kPi / 8) / 4 * 1080 / 16; }
};

TEST(FactorPolicy, SphereDiameterOnAFacingQuadMatchesTheHandFactor) {
  const FacingQuad quad;
  lod::FactorPolicy policy = *lod::parseFactorPolicy("sphere_diameter");
  ASSERT_EQ(policy.target, 8);
  const lod::FactorParams params =
      lod::factorParams(policy, quad.view, tess::Spacing::kFractionalOdd, 1);
  for (int e = 0; e < 4; ++e) {
    const float factor = lod::edgeFactor(params, quad.corners[(e + 3) % 4], quad.corners[e]);
    EXPECT_NEAR(factor, FacingQuad::handFactor(), 1e-4) << "edge " << e;
  }
  // Fractional odd keeps the factor; integer rounds it up to 41.
  const tess::Levels odd = lod::policyLevels(params, techniques::PatchDomain::kQuad, quad.corners);
  EXPECT_NEAR(odd.outer[0], FacingQuad::handFactor(), 1e-4);
  EXPECT_EQ(odd.inner[0], odd.outer[0]);
  const tess::Levels integer =
      lod::policyLevels(lod::factorParams(policy, quad.view, tess::Spacing::kInteger, 1),
                        techniques::PatchDomain::kQuad, quad.corners);
  for (int e = 0; e < 4; ++e) EXPECT_EQ(integer.outer[e], 41.0f);
  EXPECT_EQ(integer.inner[0], 41.0f);
  EXPECT_EQ(integer.inner[1], 41.0f);

  // Every edge of the generated triangles lies within [0.5, 2] x 8 px on screen: the axis
  // edges are 325.9 / 41 = 7.95 px, the diagonals sqrt(2) times that.
  const tess::Tessellation t =
      tess::tessellate(tess::Domain::kQuad, tess::Spacing::kInteger, integer);
  auto pixel = [&](const tess::DomainPoint& p) {
    const double x = -0.5 + p[0], y = -0.5 + p[1];
    const view::ProjectedPoint q = view::projectToPixels(quad.view, x, y, 0);
    return std::array<double, 2>{q.x_px, q.y_px};
  };
  size_t edges = 0;
  for (const auto& tri : t.triangles) {
    for (int k = 0; k < 3; ++k) {
      const auto a = pixel(t.points[tri[k]]), b = pixel(t.points[tri[(k + 1) % 3]]);
      const double px = std::hypot(a[0] - b[0], a[1] - b[1]);
      EXPECT_GE(px, 0.5 * 8);
      EXPECT_LE(px, 2.0 * 8);
      ++edges;
    }
  }
  EXPECT_EQ(edges, 3u * 2 * 41 * 41);
}

TEST(FactorPolicy, SharedEdgesGetTheSameFactorOnlyWhenTheOrderIsCanonical) {
  // Two patches running one edge in opposite directions: the canonical order gives both
  // the same bits at every view; patch order differs at some view.
  const lod::FactorCorner a{{0.1f, 0.37f, -0.29f}, {0, 0, 1}}, b{{1.3f, 0.77f, 0.11f}, {0, 1, 0}};
  size_t differing = 0;
  for (int i = 0; i < 64; ++i) {
    const view::View view = viewFrom({3.0 + 0.1 * i, 0.7 - 0.03 * i, 2.0 + 0.07 * i}, {0.5, 0.5, 0},
                                     45, 1920, 1080, 0.01, 100);
    for (const char* name :
         {"distance", "sphere_diameter", "lp2_edge", "lp2_edge_silhouette", "lp2_edge_roundness"}) {
      const lod::FactorParams params = lod::factorParams(*lod::parseFactorPolicy(name), view,
                                                         tess::Spacing::kFractionalOdd, 2.0);
      EXPECT_EQ(std::bit_cast<uint32_t>(lod::edgeFactor(params, a, b)),
                std::bit_cast<uint32_t>(lod::edgeFactor(params, b, a)))
          << name;
    }
    const lod::FactorParams sloppy =
        lod::factorParams(*lod::parseFactorPolicy("sphere_diameter_order_dependent"), view,
                          tess::Spacing::kFractionalOdd, 2);
    differing += lod::edgeFactor(sloppy, a, b) != lod::edgeFactor(sloppy, b, a);
  }
  EXPECT_GT(differing, 0u);
}

TEST(FactorPolicy, ReductionsScaleWithinMinScaleAndOne) {
  const view::View view = viewFrom({0, 0, 4}, {0, 0, 0}, 45, 1920, 1080, 0.1, 100);
  const lod::FactorCorner flat_a{{-0.5f, 0, 0}, {0, 0, 1}}, flat_b{{0.5f, 0, 0}, {0, 0, 1}};
  const lod::FactorCorner side_a{{-0.5f, 0, 0}, {1, 0, 0}}, side_b{{0.5f, 0, 0}, {1, 0, 0}};
  const lod::FactorParams base = lod::factorParams(*lod::parseFactorPolicy("lp2_edge"), view,
                                                   tess::Spacing::kFractionalOdd, 1);
  const lod::FactorParams silhouette = lod::factorParams(
      *lod::parseFactorPolicy("lp2_edge_silhouette"), view, tess::Spacing::kFractionalOdd, 1);
  const lod::FactorParams roundness = lod::factorParams(
      *lod::parseFactorPolicy("lp2_edge_roundness"), view, tess::Spacing::kFractionalOdd, 1);
  const float full = lod::edgeFactor(base, flat_a, flat_b);
  // Facing the camera: s_min (0.25); at the silhouette (normals across the view): full.
  EXPECT_NEAR(lod::edgeFactor(silhouette, flat_a, flat_b), 0.25 * full, 1e-5 * full);
  EXPECT_NEAR(lod::edgeFactor(silhouette, side_a, side_b), full, 1e-5 * full);
  // Parallel end normals: flat, s_min; normals 90 degrees apart (> 20): full.
  EXPECT_NEAR(lod::edgeFactor(roundness, flat_a, flat_b), 0.25 * full, 1e-5 * full);
  EXPECT_NEAR(lod::edgeFactor(roundness, flat_a, side_b), full, 1e-5 * full);
}

// Every policy's twin equals the levels the technique's own TCS writes, bit for bit, on
// one asset per technique, at views near and far, for every spacing and reduction.
TEST(FactorPolicyGpu, TwinEqualsEveryTechniqueTcsBitwise) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::pair<const char*, const char*> cases[] = {
      {"acc", "opensubdiv/catmark_xord_interior.obj"},
      {"gregory_acc", "opensubdiv/catmark_nonquads.obj"},
      {"pn_triangles", "tessbench/tri_torus.obj"},
      {"phong", "tessbench/cylinder_seam.obj"}};
  const char* policies[] = {"uniform",
                            "distance",
                            "sphere_diameter",
                            "lp2_edge",
                            "lp2_edge_silhouette",
                            "lp2_edge_roundness",
                            "sphere_diameter_order_dependent"};
  const tess::Spacing spacings[] = {tess::Spacing::kInteger, tess::Spacing::kPow2,
                                    tess::Spacing::kFractionalOdd, tess::Spacing::kFractionalEven};
  for (const auto& [technique_id, asset] : cases) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(technique_id);
    ASSERT_NE(technique, nullptr);
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath(asset));
    const techniques::BuiltSurface surface =
        techniques::buildSurface(*technique, mesh, technique->variants().front());
    const lod::FactorCorners corners = lod::factorCorners(*surface);
    const mesh::Aabb bounds = mesh::boundsOf(surface->controlMesh());
    const double diagonal = length(bounds.max - bounds.min);
    const std::vector<gpu::GpuPatchProgram> programs = surface->gpuPrograms();
    ASSERT_FALSE(programs.empty()) << technique_id;
    size_t compared = 0, differing = 0;
    int combination = 0;
    for (const view::View& view : viewsAround(bounds)) {
      for (const char* name : policies) {
        for (tess::Spacing spacing : spacings) {
          lod::FactorPolicy policy = *lod::parseFactorPolicy(name);
          policy.reduction = lod::InnerReduction(combination++ % 3);
          const lod::FactorParams params = lod::factorParams(policy, view, spacing, diagonal);
          const std::vector<tess::Levels> twin = lod::policyLevels(params, corners);
          for (const gpu::GpuPatchProgram& program : programs) {
            std::vector<tess::Levels> expected(program.patch_count);
            for (uint32_t i = 0; i < program.patch_count; ++i) {
              expected[i] = twin[program.patch_ids.empty() ? i : program.patch_ids[i]];
            }
            const gpu::TcsFactorPolicy device_policy =
                lod::tcsFactorPolicy(params, corners, program);
            const gpu::PatchProgramCapture capture =
                gpu::runPatchProgram(context, program, expected,
                                     {.spacing = spacing,
                                      .patches_per_draw = 64,
                                      .capture = false,
                                      .statistics = false,
                                      .factor_policy = &device_policy});
            ASSERT_EQ(capture.tcs_levels.size(), program.patch_count);
            for (uint32_t i = 0; i < program.patch_count; ++i) {
              ++compared;
              if (capture.tcs_levels[i] != tess::levelsBits(expected[i])) {
                if (++differing <= 3) {
                  ADD_FAILURE() << technique_id << " " << name << " spacing "
                                << tess::toString(spacing) << " patch " << i << ": TCS outer0 "
                                << std::bit_cast<float>(capture.tcs_levels[i][0]) << " twin "
                                << expected[i].outer[0];
                }
              }
            }
          }
        }
      }
    }
    EXPECT_GT(compared, 0u);
    EXPECT_EQ(differing, 0u) << technique_id;
  }
}

}  // namespace
}  // namespace tb
