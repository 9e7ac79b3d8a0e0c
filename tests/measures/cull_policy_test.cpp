// Culling policies (harness/lod/cull_policy.h): hand-made cases with known answers, and
// the CPU twin against the decisions every technique's own TCS makes on the device
// (shaders/common/cull.glsl) on every frame of the bundled camera paths.
#include "harness/lod/cull_policy.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/gpu/patch_program.h"
#include "core/mesh/obj_loader.h"
#include "core/view/camera.h"
#include "harness/lod/tangent_plane.h"
#include "harness/measures/common/instruction_counts/instructions.h"
#include "harness/measures/culling/culling_cost.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr double kPi = std::numbers::pi;

view::View viewFrom(const mesh::Vec3d& eye, const mesh::Vec3d& target, double near_plane,
                    double far_plane) {
  return view::perspectiveView({.eye = eye,
                                .target = target,
                                .width_px = 1920,
                                .height_px = 1080,
                                .near_plane = near_plane,
                                .far_plane = far_plane});
}

// One flat quad patch in the plane z = 0 facing +z, corners (-1,-1), (1,-1), (1,1), (-1,1),
// with its tangent-plane coefficients as a bicubic patch (u along x, v along y).
lod::CullPatchBounds flatQuad(double offset_x = 0) {
  lod::CullPatchBounds patch;
  const double xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int c = 0; c < 4; ++c) {
    patch.corner_position[c] = {float(xy[c][0] + offset_x), float(xy[c][1]), 0};
    patch.corner_normal[c] = {0, 0, 1};
    patch.hull.push_back(patch.corner_position[c]);
  }
  patch.cone_axis = {0, 0, 1};
  patch.cone_sine = 0;
  techniques::PatchCullBounds net;
  net.bezier_degree = 3;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i)
      net.bezier_net.push_back({offset_x - 1 + 2 * i / 3.0, -1 + 2 * j / 3.0, 0});
  }
  double normal_max = 0;
  for (const auto& c :
       lod::tangentPlaneCoefficients(techniques::PatchDomain::kQuad, net, net.bezier_net[0])) {
    patch.tangent_plane.push_back({float(c[0]), float(c[1]), float(c[2]), float(c[3])});
    normal_max = std::max(normal_max, std::hypot(c[0], c[1], c[2]));
  }
  patch.tangent_normal_max = float(normal_max);
  return patch;
}

lod::CullBounds boundsOfOne(const lod::CullPatchBounds& patch) {
  lod::CullBounds bounds;
  bounds.patches = {patch};
  bounds.global_margin = 0.1f;
  return bounds;
}

TEST(CullPolicy, NamesRoundTripAndOnlyHullConeAndTangentPlaneAreConservative) {
  ASSERT_EQ(lod::allCullPolicies().size(), 9u);
  EXPECT_EQ(lod::allCullPolicies().front(), lod::CullPolicy::kNone);
  for (lod::CullPolicy policy : lod::allCullPolicies()) {
    EXPECT_EQ(lod::parseCullPolicy(lod::cullPolicyName(policy)), policy);
    EXPECT_FALSE(lod::cullPolicyDescription(policy).empty());
  }
  EXPECT_FALSE(lod::parseCullPolicy("frustum"));
  EXPECT_TRUE(lod::isConservative(lod::CullPolicy::kCone));
  EXPECT_TRUE(lod::isConservative(lod::CullPolicy::kTangentPlane));
  EXPECT_TRUE(lod::isConservative(lod::CullPolicy::kTangentPlaneFrustum));
  EXPECT_FALSE(lod::isConservative(lod::CullPolicy::kBackfaceLp2));
  EXPECT_FALSE(lod::isConservative(lod::CullPolicy::kFrustumLp2Exact));
}

// A flat quad facing +z: seen from the front nothing culls it; from behind, every back-face
// policy does and no frustum policy does; moved off screen, every frustum policy does.
// What each policy costs per patch in cull data, from TbCullPatch's layout (cull.glsl): a
// quad with a 16-point hull; a policy's halves name its back-facing and frustum tests.
TEST(CullPolicy, BytesPerPatchFollowTheLayoutAndHalvesSplitCombined) {
  lod::CullPatchBounds quad;
  quad.corner_count = 4;
  quad.hull.assign(16, mesh::Vec3f{0, 0, 0});
  lod::CullPatchBounds triangle = quad;
  triangle.corner_count = 3;
  triangle.hull.resize(10);
  const std::vector<lod::CullPatchBounds> both = {quad, triangle};
  using P = lod::CullPolicy;
  EXPECT_EQ(lod::cullBytesPerPatch(P::kNone, both), 0);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kBackfaceLp2, {quad}), 16 + 2 * 64);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kFrustumLp2Exact, {triangle}), 16 + 48);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kFrustumHull, {quad}), 16 + 256);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kCone, both), 16 + 16 + (256 + 160) / 2.0);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kCombined, both), lod::cullBytesPerPatch(P::kCone, both));
  EXPECT_EQ(lod::cullPolicyHalves(P::kCombined).back_facing, P::kCone);
  EXPECT_EQ(lod::cullPolicyHalves(P::kCombined).outside_frustum, P::kFrustumHull);
  EXPECT_EQ(lod::cullPolicyHalves(P::kBackfaceLp2).outside_frustum, P::kNone);
  EXPECT_EQ(lod::cullPolicyHalves(P::kFrustumLp2Global).back_facing, P::kNone);
  EXPECT_EQ(lod::cullPolicyHalves(P::kNone).back_facing, P::kNone);
  // tangent_plane: its header and 81 coefficients where the patch has them, else the cone.
  lod::CullPatchBounds bicubic = quad;
  bicubic.tangent_plane.resize(81);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kTangentPlane, {bicubic}), 16 + 16 + 16 + 81 * 16);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kTangentPlane, {quad}), 16 + 16 + 16 + 256);
  EXPECT_EQ(lod::cullBytesPerPatch(P::kTangentPlaneFrustum, {bicubic}),
            16 + 16 + 16 + 81 * 16 + 256);
  EXPECT_EQ(lod::cullPolicyHalves(P::kTangentPlaneFrustum).back_facing, P::kTangentPlane);
  EXPECT_EQ(lod::cullPolicyHalves(P::kTangentPlaneFrustum).outside_frustum, P::kFrustumHull);
}

// Each policy's TCS cost, counted with the policy fixed at compile time: none adds nothing,
// every other policy something, combined at least its two halves' larger; the control, the
// TCS with the policy read at run time (kTbCullPolicy = 1), carries every policy's code and
// counts more than any one of them.
TEST(CullPolicy, EachPolicysTcsCostIsCountedApart) {
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_torus.obj"));
  const techniques::Technique* acc = techniques::TechniqueRegistry::instance().find("acc");
  ASSERT_NE(acc, nullptr);
  const techniques::BuiltSurface patches =
      techniques::buildSurface(*acc, mesh, acc->variants().front());
  const auto policies = lod::allCullPolicies();
  const std::vector<measures::CullTcsCost> costs = measures::cullTcsCosts(*patches, policies);
  ASSERT_EQ(costs.size(), policies.size());
  ASSERT_EQ(policies[0], lod::CullPolicy::kNone);
  EXPECT_EQ(costs[0].cull_instructions, 0);
  double cone = 0, hull = 0, combined = 0, largest = 0;
  for (size_t k = 1; k < costs.size(); ++k) {
    EXPECT_GT(costs[k].cull_instructions, 10) << lod::cullPolicyName(policies[k]);
    largest = std::max(largest, costs[k].tcs_instructions);
    if (policies[k] == lod::CullPolicy::kCone) cone = costs[k].cull_instructions;
    if (policies[k] == lod::CullPolicy::kFrustumHull) hull = costs[k].cull_instructions;
    if (policies[k] == lod::CullPolicy::kCombined) combined = costs[k].cull_instructions;
  }
  EXPECT_GE(combined, std::max(cone, hull));
  const gpu::GpuPatchProgram program = patches->gpuPrograms().front();
  const double runtime = double(
      measures::countEmbeddedShader(program.control_shader, program.specialization, {{202, 1}})
          .vector.total());
  EXPECT_GT(runtime, largest) << "the run-time switch holds every policy";
}

TEST(CullPolicy, FlatQuadFrontBackAndOffScreen) {
  const lod::CullBounds bounds = boundsOfOne(flatQuad());
  const view::View front = viewFrom({0, 0.5, 10}, {0, 0, 0}, 0.1, 100);
  const view::View back = viewFrom({0, 0.5, -10}, {0, 0, 0}, 0.1, 100);
  for (lod::CullPolicy policy : lod::allCullPolicies()) {
    EXPECT_FALSE(lod::cullsPatch(lod::cullParams(policy, front, bounds), bounds.patches[0]))
        << lod::cullPolicyName(policy);
  }
  auto culledFromBack = [&](lod::CullPolicy policy) {
    return lod::cullsPatch(lod::cullParams(policy, back, bounds), bounds.patches[0]);
  };
  EXPECT_TRUE(culledFromBack(lod::CullPolicy::kBackfaceLp2));
  EXPECT_TRUE(culledFromBack(lod::CullPolicy::kCone));
  EXPECT_TRUE(culledFromBack(lod::CullPolicy::kCombined));
  EXPECT_TRUE(culledFromBack(lod::CullPolicy::kTangentPlane));
  EXPECT_TRUE(culledFromBack(lod::CullPolicy::kTangentPlaneFrustum));
  EXPECT_FALSE(culledFromBack(lod::CullPolicy::kFrustumHull));
  EXPECT_FALSE(culledFromBack(lod::CullPolicy::kFrustumLp2Global));

  // 45 units to the side at 10 units' distance: far outside a 45 degree field of view.
  const lod::CullBounds aside = boundsOfOne(flatQuad(45));
  for (lod::CullPolicy policy :
       {lod::CullPolicy::kFrustumLp2Global, lod::CullPolicy::kFrustumLp2Exact,
        lod::CullPolicy::kFrustumHull, lod::CullPolicy::kCombined,
        lod::CullPolicy::kTangentPlaneFrustum}) {
    EXPECT_TRUE(lod::cullsPatch(lod::cullParams(policy, front, aside), aside.patches[0]))
        << lod::cullPolicyName(policy);
  }
}

// Grazing: the eye in the quad's plane sees it edge-on; the cone of a flat patch (half angle
// 0) does not cull it, nor does a cone wider than the angle to the eye.
TEST(CullPolicy, ConeKeepsAPatchSeenEdgeOnOrWithinItsHalfAngle) {
  lod::CullPatchBounds patch = flatQuad();
  const view::View edge_on = viewFrom({0, -20, 0}, {0, 0, 0}, 0.1, 100);
  lod::CullBounds bounds = boundsOfOne(patch);
  EXPECT_FALSE(
      lod::cullsPatch(lod::cullParams(lod::CullPolicy::kCone, edge_on, bounds), bounds.patches[0]));
  // The eye behind the plane at 30 degrees below it: a 20 degree cone culls, a 40 one keeps.
  const double a = 30 * kPi / 180;
  const view::View below = viewFrom({0, -20 * std::cos(a), -20 * std::sin(a)}, {0, 0, 0}, 0.1, 100);
  patch.cone_sine = float(std::sin(20 * kPi / 180));
  bounds = boundsOfOne(patch);
  EXPECT_TRUE(
      lod::cullsPatch(lod::cullParams(lod::CullPolicy::kCone, below, bounds), bounds.patches[0]));
  patch.cone_sine = float(std::sin(40 * kPi / 180));
  bounds = boundsOfOne(patch);
  EXPECT_FALSE(
      lod::cullsPatch(lod::cullParams(lod::CullPolicy::kCone, below, bounds), bounds.patches[0]));
  // No cone (sine > 1): never culled.
  patch.cone_sine = 2;
  bounds = boundsOfOne(patch);
  EXPECT_FALSE(
      lod::cullsPatch(lod::cullParams(lod::CullPolicy::kCone, below, bounds), bounds.patches[0]));
}

// The tangent plane of a flat patch seen edge-on is 0 on the whole domain: kept. Slightly
// below the plane it culls; the same patch with its coefficients' sign flipped (a wrong
// convention, the control) culls from the front instead and keeps it from behind.
TEST(CullPolicy, TangentPlaneKeepsAPatchSeenEdgeOnAndFollowsItsSign) {
  lod::CullPatchBounds patch = flatQuad();
  patch.cone_sine = 2;  // no cone: the tangent-plane half alone
  const auto culls = [](const lod::CullPatchBounds& p, const view::View& view) {
    return lod::cullsPatch(lod::cullParams(lod::CullPolicy::kTangentPlane, view, boundsOfOne(p)),
                           p);
  };
  const view::View edge_on = viewFrom({0, -20, 0}, {0, 0, 0}, 0.1, 100);
  const view::View below = viewFrom({0, -20, -1}, {0, 0, 0}, 0.1, 100);
  const view::View above = viewFrom({0, -20, 1}, {0, 0, 0}, 0.1, 100);
  EXPECT_FALSE(culls(patch, edge_on));
  EXPECT_TRUE(culls(patch, below));
  EXPECT_FALSE(culls(patch, above));
  for (auto& c : patch.tangent_plane) {
    for (float& v : c) v = -v;
  }
  EXPECT_TRUE(culls(patch, above));
  EXPECT_FALSE(culls(patch, below));
}

// The frustum planes are unit-normal and contain what the view sees: the target point is
// inside all six, a point behind the eye is outside the near plane.
TEST(CullPolicy, FrustumPlanesAreUnitAndBoundTheView) {
  const view::View view = viewFrom({3, 2, 10}, {0, 0, 0}, 0.5, 50);
  const lod::CullParams params =
      lod::cullParams(lod::CullPolicy::kFrustumHull, view, boundsOfOne(flatQuad()));
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
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(technique_id);
    ASSERT_NE(technique, nullptr);
    const techniques::BuiltSurface surface = techniques::buildSurface(
        *technique, mesh::loadObjFile(testing::assetPath(asset)), technique->variants().front());
    const mesh::Aabb box = mesh::boundsOf(surface->controlMesh());
    const lod::CullBounds bounds =
        lod::cullBounds(*surface, lod::factorCorners(*surface), length(box.max - box.min), 16);
    const std::vector<gpu::GpuPatchProgram> programs = surface->gpuPrograms();
    ASSERT_FALSE(programs.empty()) << technique_id;
    const tess::Levels level_one{};
    std::map<lod::CullPolicy, std::pair<size_t, size_t>> culled_and_compared;
    size_t differing = 0;
    for (const char* path : {"orbit", "dolly", "flyby"}) {
      const view::CameraPath sampled =
          suite::sampleCameraPath(suite::resolveCameraPath(path), box, 0);
      for (size_t f = 0; f < sampled.views.size(); ++f) {
        for (lod::CullPolicy policy : lod::allCullPolicies()) {
          if (policy == lod::CullPolicy::kNone) continue;
          const lod::CullParams params = lod::cullParams(policy, sampled.views[f], bounds);
          const std::vector<uint8_t> twin = lod::cullDecisions(params, bounds);
          for (const gpu::GpuPatchProgram& program : programs) {
            const gpu::TcsCullPolicy device_policy = lod::tcsCullPolicy(params, bounds, program);
            const gpu::PatchProgramCapture capture =
                gpu::runPatchProgram(context, program, level_one,
                                     {.patches_per_draw = 256,
                                      .capture = false,
                                      .statistics = false,
                                      .cull_policy = &device_policy});
            ASSERT_EQ(capture.tcs_levels.size(), program.patch_count);
            for (uint32_t i = 0; i < program.patch_count; ++i) {
              const size_t patch = program.patch_ids.empty() ? i : program.patch_ids[i];
              const bool device_culled = std::bit_cast<float>(capture.tcs_levels[i][0]) == 0.0f;
              auto& [culled, compared] = culled_and_compared[policy];
              ++compared;
              culled += twin[patch];
              if (device_culled != (twin[patch] != 0) && ++differing <= 5) {
                ADD_FAILURE() << technique_id << " " << lod::cullPolicyName(policy) << " " << path
                              << " frame " << f << " patch " << patch << ": TCS " << device_culled
                              << ", twin " << int(twin[patch]);
              }
            }
          }
        }
      }
    }
    EXPECT_EQ(differing, 0u) << technique_id;
    // Non-trivial decisions: every policy culls some patches somewhere and keeps others.
    for (const auto& [policy, counts] : culled_and_compared) {
      EXPECT_GT(counts.first, 0u) << technique_id << " " << lod::cullPolicyName(policy);
      EXPECT_LT(counts.first, counts.second) << technique_id << " " << lod::cullPolicyName(policy);
    }
  }
}

}  // namespace
}  // namespace tb
