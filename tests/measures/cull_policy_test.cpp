// Culling policies (harness/lod/cull_policy.h): hand-made cases with known answers, and
// the CPU twin against the decisions every technique's own TCS makes on the device
// (shaders/common/cull.glsl) on every frame of the bundled camera paths.
#include "harness/lod/cull_policy.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>

#include "core/gpu/patch_program.h"
#include "core/mesh/obj_loader.h"
#include "core/view/camera.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr double kPi = std::numbers::pi;

View viewFrom(const Vec3d& eye, const Vec3d& target, double near_plane, double far_plane) {
  return perspectiveView({.eye = eye, .target = target, .width_px = 1920, .height_px = 1080,
                          .near_plane = near_plane, .far_plane = far_plane});
}

// One flat quad patch in the plane z = 0 facing +z, corners (-1,-1), (1,-1), (1,1), (-1,1).
CullPatchBounds flatQuad(double offset_x = 0) {
  CullPatchBounds patch;
  const double xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int c = 0; c < 4; ++c) {
    patch.corner_position[c] = {float(xy[c][0] + offset_x), float(xy[c][1]), 0};
    patch.corner_normal[c] = {0, 0, 1};
    patch.hull.push_back(patch.corner_position[c]);
  }
  patch.cone_axis = {0, 0, 1};
  patch.cone_sine = 0;
  return patch;
}

CullBounds boundsOfOne(const CullPatchBounds& patch) {
  CullBounds bounds;
  bounds.patches = {patch};
  bounds.global_margin = 0.1f;
  return bounds;
}

TEST(CullPolicy, NamesRoundTripAndOnlyHullAndConeAreConservative) {
  ASSERT_EQ(allCullPolicies().size(), 7u);
  EXPECT_EQ(allCullPolicies().front(), CullPolicy::kNone);
  for (CullPolicy policy : allCullPolicies()) {
    EXPECT_EQ(parseCullPolicy(cullPolicyName(policy)), policy);
    EXPECT_FALSE(cullPolicyDescription(policy).empty());
  }
  EXPECT_FALSE(parseCullPolicy("frustum"));
  EXPECT_TRUE(isConservative(CullPolicy::kCone));
  EXPECT_FALSE(isConservative(CullPolicy::kBackfaceLp2));
}

// A flat quad facing +z: seen from the front nothing culls it; from behind, every back-face
// policy does and no frustum policy does; moved off screen, every frustum policy does.
TEST(CullPolicy, FlatQuadFrontBackAndOffScreen) {
  const CullBounds bounds = boundsOfOne(flatQuad());
  const View front = viewFrom({0, 0.5, 10}, {0, 0, 0}, 0.1, 100);
  const View back = viewFrom({0, 0.5, -10}, {0, 0, 0}, 0.1, 100);
  for (CullPolicy policy : allCullPolicies()) {
    EXPECT_FALSE(cullsPatch(cullParams(policy, front, bounds), bounds.patches[0]))
        << cullPolicyName(policy);
  }
  auto culledFromBack = [&](CullPolicy policy) {
    return cullsPatch(cullParams(policy, back, bounds), bounds.patches[0]);
  };
  EXPECT_TRUE(culledFromBack(CullPolicy::kBackfaceLp2));
  EXPECT_TRUE(culledFromBack(CullPolicy::kCone));
  EXPECT_TRUE(culledFromBack(CullPolicy::kCombined));
  EXPECT_FALSE(culledFromBack(CullPolicy::kFrustumHull));
  EXPECT_FALSE(culledFromBack(CullPolicy::kFrustumLp2Global));

  // 45 units to the side at 10 units' distance: far outside a 45 degree field of view.
  const CullBounds aside = boundsOfOne(flatQuad(45));
  for (CullPolicy policy : {CullPolicy::kFrustumLp2Global, CullPolicy::kFrustumLp2Exact,
                            CullPolicy::kFrustumHull, CullPolicy::kCombined}) {
    EXPECT_TRUE(cullsPatch(cullParams(policy, front, aside), aside.patches[0]))
        << cullPolicyName(policy);
  }
}

// Grazing: the eye in the quad's plane sees it edge-on; the cone of a flat patch (half angle
// 0) does not cull it, nor does a cone wider than the angle to the eye.
TEST(CullPolicy, ConeKeepsAPatchSeenEdgeOnOrWithinItsHalfAngle) {
  CullPatchBounds patch = flatQuad();
  const View edge_on = viewFrom({0, -20, 0}, {0, 0, 0}, 0.1, 100);
  CullBounds bounds = boundsOfOne(patch);
  EXPECT_FALSE(cullsPatch(cullParams(CullPolicy::kCone, edge_on, bounds), bounds.patches[0]));
  // The eye behind the plane at 30 degrees below it: a 20 degree cone culls, a 40 one keeps.
  const double a = 30 * kPi / 180;
  const View below = viewFrom({0, -20 * std::cos(a), -20 * std::sin(a)}, {0, 0, 0}, 0.1, 100);
  patch.cone_sine = float(std::sin(20 * kPi / 180));
  bounds = boundsOfOne(patch);
  EXPECT_TRUE(cullsPatch(cullParams(CullPolicy::kCone, below, bounds), bounds.patches[0]));
  patch.cone_sine = float(std::sin(40 * kPi / 180));
  bounds = boundsOfOne(patch);
  EXPECT_FALSE(cullsPatch(cullParams(CullPolicy::kCone, below, bounds), bounds.patches[0]));
  // No cone (sine > 1): never culled.
  patch.cone_sine = 2;
  bounds = boundsOfOne(patch);
  EXPECT_FALSE(cullsPatch(cullParams(CullPolicy::kCone, below, bounds), bounds.patches[0]));
}

// The frustum planes are unit-normal and contain what the view sees: the target point is
// inside all six, a point behind the eye is outside the near plane.
TEST(CullPolicy, FrustumPlanesAreUnitAndBoundTheView) {
  const View view = viewFrom({3, 2, 10}, {0, 0, 0}, 0.5, 50);
  const CullParams params = cullParams(CullPolicy::kFrustumHull, view, boundsOfOne(flatQuad()));
  for (const auto& plane : params.planes) {
    EXPECT_NEAR(std::hypot(plane[0], plane[1], plane[2]), 1.0, 1e-6);
    EXPECT_GT(plane[0] * 0 + plane[1] * 0 + plane[2] * 0 + plane[3], 0);  // the target
  }
  const auto& near = params.planes[4];
  EXPECT_LT(near[0] * 6 + near[1] * 4 + near[2] * 20 + near[3], 0);  // behind the eye
}

// Acceptance 1: on every frame of orbit, dolly and flyby, each policy's twin makes the same
// decision as each technique's own TCS for every patch.
TEST(CullPolicyGpu, TwinEqualsEveryTechniqueTcsOnEveryFrameOfTheBundledPaths) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::pair<const char*, const char*> cases[] = {
      {"acc", "opensubdiv/catmark_xord_interior.obj"},
      {"gregory_acc", "opensubdiv/catmark_nonquads.obj"},
      {"pn_triangles", "tessbench/tri_torus.obj"},
      {"phong", "tessbench/cylinder_seam.obj"}};
  for (const auto& [technique_id, asset] : cases) {
    const Technique* technique = TechniqueRegistry::instance().find(technique_id);
    ASSERT_NE(technique, nullptr);
    const BuiltSurface surface = buildSurface(*technique, loadObjFile(testing::assetPath(asset)),
                                              technique->variants().front());
    const Aabb box = boundsOf(surface->controlMesh());
    const CullBounds bounds =
        cullBounds(*surface, factorCorners(*surface), length(box.max - box.min));
    const std::vector<gpu::GpuPatchProgram> programs = surface->gpuPrograms();
    ASSERT_FALSE(programs.empty()) << technique_id;
    const tess::Levels level_one{};
    std::map<CullPolicy, std::pair<size_t, size_t>> culled_and_compared;
    size_t differing = 0;
    for (const char* path : {"orbit", "dolly", "flyby"}) {
      const CameraPath sampled = sampleCameraPath(resolveCameraPath(path), box, 0);
      for (size_t f = 0; f < sampled.views.size(); ++f) {
        for (CullPolicy policy : allCullPolicies()) {
          if (policy == CullPolicy::kNone) continue;
          const CullParams params = cullParams(policy, sampled.views[f], bounds);
          const std::vector<uint8_t> twin = cullDecisions(params, bounds);
          for (const gpu::GpuPatchProgram& program : programs) {
            const gpu::TcsCullPolicy device_policy = tcsCullPolicy(params, bounds, program);
            const gpu::PatchProgramCapture capture = gpu::runPatchProgram(
                context, program, level_one,
                {.patches_per_draw = 256, .capture = false, .statistics = false,
                 .cull_policy = &device_policy});
            ASSERT_EQ(capture.tcs_levels.size(), program.patch_count);
            for (uint32_t i = 0; i < program.patch_count; ++i) {
              const size_t patch = program.patch_ids.empty() ? i : program.patch_ids[i];
              const bool device_culled = std::bit_cast<float>(capture.tcs_levels[i][0]) == 0.0f;
              auto& [culled, compared] = culled_and_compared[policy];
              ++compared;
              culled += twin[patch];
              if (device_culled != (twin[patch] != 0) && ++differing <= 5) {
                ADD_FAILURE() << technique_id << " " << cullPolicyName(policy) << " " << path
                              << " frame " << f << " patch " << patch << ": TCS "
                              << device_culled << ", twin " << int(twin[patch]);
              }
            }
          }
        }
      }
    }
    EXPECT_EQ(differing, 0u) << technique_id;
    // Non-trivial decisions: every policy culls some patches somewhere and keeps others.
    for (const auto& [policy, counts] : culled_and_compared) {
      EXPECT_GT(counts.first, 0u) << technique_id << " " << cullPolicyName(policy);
      EXPECT_LT(counts.first, counts.second) << technique_id << " " << cullPolicyName(policy);
    }
  }
}

}  // namespace
}  // namespace tb
