// The culling measure's acceptance over real techniques (harness/measures/culling/culling.h): the
// conservative policies make no false cull on any bundled asset along the bundled paths; on
// a refined convex cube the cone culls a good share of the patches but never more than the
// oracle's back-facing count; a patch straddling the silhouette is never conservatively
// culled; the device's counts equal the CPU tessellator's.
#include "harness/measures/culling/culling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <span>

#include "core/mesh/normals.h"
#include "core/mesh/obj_loader.h"
#include "core/osd/uniform_refinement.h"
#include "core/view/camera.h"
#include "harness/measures/culling/cull_oracle.h"
#include "harness/suite/camera_path.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr lod::CullPolicy kConservative[] = {
    lod::CullPolicy::kFrustumHull, lod::CullPolicy::kCone, lod::CullPolicy::kCombined,
    lod::CullPolicy::kTangentPlane, lod::CullPolicy::kTangentPlaneFrustum};
// The conservative tests apart: combined and tangent_plane_frustum cull exactly what one of
// their halves culls (checked per frame below), so their false culls are their halves'.
constexpr lod::CullPolicy kConservativeTests[] = {
    lod::CullPolicy::kFrustumHull, lod::CullPolicy::kCone, lod::CullPolicy::kTangentPlane};

techniques::BuiltSurface buildDefault(const char* technique_id, const mesh::Mesh& mesh) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  if (technique == nullptr) throw std::runtime_error(std::string("no technique ") + technique_id);
  return techniques::buildSurface(*technique, mesh, technique->variants().front());
}

view::View viewFrom(const mesh::Vec3d& eye, const mesh::Vec3d& target, double near_plane,
                    double far_plane) {
  return view::perspectiveView({.eye = eye,
                                .target = target,
                                .width_px = 960,
                                .height_px = 540,
                                .near_plane = near_plane,
                                .far_plane = far_plane});
}

// Views of `mesh` from `diameters` bounding-box diagonals away, from six scattered directions.
std::vector<view::View> viewsFromAfar(const mesh::Mesh& mesh, double diameters) {
  const mesh::Aabb box = mesh::boundsOf(mesh);
  const mesh::Vec3d centre = 0.5 * (box.min + box.max);
  const double diagonal = length(box.max - box.min);
  std::vector<view::View> views;
  for (int i = 0; i < 6; ++i) {
    const double azimuth = 0.4 + 1.1 * i, elevation = 0.6 - 0.25 * i;
    const mesh::Vec3d direction{std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                                std::cos(elevation) * std::cos(azimuth)};
    views.push_back(viewFrom(centre + diameters * diagonal * direction, centre, 0.01 * diagonal,
                             100 * diagonal));
  }
  return views;
}

mesh::Mesh refinedConvex(const char* asset, osd::Scheme scheme, int levels) {
  mesh::Mesh mesh =
      osd::refineUniform(mesh::loadObjFile(testing::assetPath(asset)), scheme, levels);
  mesh::assignAngleWeightedNormals(&mesh);
  return mesh;
}

// Acceptance 3: catmark_cube refined three times (384 quads, closed, convex), seen from 10
// diagonals: the cone culls at least 35% of the patches and never more than the patches
// the oracle finds back-facing or outside; likewise for the Gregory patches of the same mesh
// and for PN and Phong on a Loop-refined icosahedron (1280 triangles).
TEST(Culling, ConeCullsAboutHalfOfAConvexMeshFromAfarAndNeverMoreThanTheOracle) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const mesh::Mesh cube =
      refinedConvex("opensubdiv/catmark_cube.obj", osd::Scheme::kCatmullClark, 3);
  ASSERT_EQ(cube.faceCount(), 384u);
  const mesh::Mesh icosahedron =
      refinedConvex("opensubdiv/loop_icosahedron.obj", osd::Scheme::kLoop, 3);
  const std::pair<const char*, const mesh::Mesh*> cases[] = {{"acc", &cube},
                                                             {"gregory_acc", &cube},
                                                             {"pn_triangles", &icosahedron},
                                                             {"phong", &icosahedron}};
  const lod::CullPolicy cone[] = {lod::CullPolicy::kCone};
  for (const auto& [technique_id, mesh] : cases) {
    const techniques::BuiltSurface patches = buildDefault(technique_id, *mesh);
    measures::CullingRun run(*patches, &context, "", {.level = 4, .render_scale = 1});
    const std::vector<view::View> views = viewsFromAfar(*mesh, 10);
    const std::vector<measures::CullingFrame> frames = run.frames(cone, views)[0];
    for (const measures::CullingFrame& f : frames) {
      ASSERT_TRUE(f.oracle_measured && f.gpu_measured) << run.gpuSkipReason();
      const double fraction = double(f.culled_patches) / double(f.patches);
      EXPECT_GE(fraction, 0.35) << technique_id << " frame " << f.frame;
      EXPECT_LE(f.culled_patches, f.cullable_patches) << technique_id << " frame " << f.frame;
      EXPECT_EQ(f.false_culls, 0u) << technique_id;
      EXPECT_EQ(f.twin_mismatches, 0u) << technique_id;
      RecordProperty(std::string(technique_id) + "_frame" + std::to_string(f.frame),
                     std::to_string(fraction));
    }
  }
}

// Efficiency by cause: each half of a policy is held to the oracle's patches of its cause.
// From afar nothing is outside the frustum; from close to one face most of the cube is. The
// halves never cull more than the oracle's count of their cause, a policy without a half
// culls nothing of that cause, combined culls at least as many as each of its halves, and
// the control (`none`) has efficiency 0.
TEST(Culling, EfficiencyByCauseHoldsEachHalfOfAPolicyToItsCause) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const mesh::Mesh cube =
      refinedConvex("opensubdiv/catmark_cube.obj", osd::Scheme::kCatmullClark, 3);
  const techniques::BuiltSurface patches = buildDefault("acc", cube);
  measures::CullingRun run(*patches, &context, "", {.level = 4, .render_scale = 0.5});
  std::vector<view::View> views = viewsFromAfar(cube, 10);
  const mesh::Aabb box = mesh::boundsOf(cube);
  const mesh::Vec3d centre = 0.5 * (box.min + box.max);
  const double diagonal = length(box.max - box.min);
  views.push_back(viewFrom(centre + mesh::Vec3d{0.1, 0.05, 0.55} * diagonal,
                           centre + mesh::Vec3d{0.35, 0.05, 0.3} * diagonal, 0.01 * diagonal,
                           100 * diagonal));
  using P = lod::CullPolicy;
  const P policies[] = {P::kNone, P::kFrustumHull, P::kCone, P::kCombined};
  const auto frames = run.frames(policies, views);
  uint64_t outside = 0, hull_outside = 0, cone_back = 0, back = 0;
  for (size_t f = 0; f < views.size(); ++f) {
    for (size_t k = 0; k < std::size(policies); ++k) {
      const measures::CullingFrame& frame = frames[k][f];
      ASSERT_TRUE(frame.oracle_measured) << run.gpuSkipReason();
      EXPECT_LE(frame.culled_cullable_patches, frame.cullable_patches);
      EXPECT_LE(frame.culled_back_facing_patches, frame.back_facing_patches);
      EXPECT_LE(frame.culled_outside_frustum_patches, frame.outside_frustum_patches);
    }
    EXPECT_EQ(frames[0][f].culled_cullable_patches, 0u) << "the control culls nothing";
    EXPECT_EQ(frames[1][f].culled_back_facing_patches, 0u) << "frustum_hull has no back half";
    EXPECT_EQ(frames[2][f].culled_outside_frustum_patches, 0u) << "cone has no frustum half";
    EXPECT_GE(frames[3][f].culled_cullable_patches,
              std::max(frames[1][f].culled_cullable_patches, frames[2][f].culled_cullable_patches));
    outside += frames[1][f].outside_frustum_patches;
    hull_outside += frames[1][f].culled_outside_frustum_patches;
    back += frames[2][f].back_facing_patches;
    cone_back += frames[2][f].culled_back_facing_patches;
  }
  EXPECT_GT(outside, 50u) << "the close view leaves most of the cube outside";
  EXPECT_GT(double(hull_outside) / double(outside), 0.5);
  EXPECT_GT(double(cone_back) / double(back), 0.5);
  const measures::CullingSummary none = measures::summarise(frames[0]);
  const measures::CullingSummary cone = measures::summarise(frames[2]);
  EXPECT_EQ(none.culled_cullable_patches, 0u);
  EXPECT_EQ(cone.culled_back_facing_patches, cone_back);
  RecordProperty("cone_back_facing_efficiency", std::to_string(double(cone_back) / double(back)));
  RecordProperty("frustum_hull_efficiency", std::to_string(double(hull_outside) / double(outside)));
}

// Acceptance 3, second half: patches whose own normals face the eye somewhere and away
// somewhere (they straddle the silhouette) are never culled by the conservative policies.
TEST(Culling, PatchesStraddlingTheSilhouetteAreNeverConservativelyCulled) {
  const mesh::Mesh cube =
      refinedConvex("opensubdiv/catmark_cube.obj", osd::Scheme::kCatmullClark, 3);
  const mesh::Mesh torus = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_torus.obj"));
  size_t straddling_seen = 0;
  for (const mesh::Mesh* mesh : {&cube, &torus}) {
    for (const char* technique_id : {"acc", "gregory_acc"}) {
      const techniques::BuiltSurface patches = buildDefault(technique_id, *mesh);
      measures::CullingRun run(*patches, nullptr, "not used", {});
      for (const view::View& view : viewsFromAfar(*mesh, 3)) {
        const mesh::Vec3d eye{view.eye[0], view.eye[1], view.eye[2]};
        for (size_t p = 0; p < patches->patchCount(); ++p) {
          // The geometric normal dp/du x dp/dv by central differences (not the shading
          // normal: the cone bounds the geometry).
          bool front = false, back = false;
          constexpr double h = 1e-5;
          auto at = [&](double u, double v) {
            return patches->evaluate(p, techniques::DomainCoord{u, v, 0}).position;
          };
          for (int i = 1; i < 8; ++i) {
            for (int j = 1; j < 8; ++j) {
              const double u = i / 8.0, v = j / 8.0;
              const mesh::Vec3d normal =
                  cross(at(u + h, v) - at(u - h, v), at(u, v + h) - at(u, v - h));
              const double facing = dot(normal, eye - at(u, v));
              front = front || facing > 0;
              back = back || facing < 0;
            }
          }
          if (!(front && back)) continue;
          ++straddling_seen;
          for (lod::CullPolicy policy : kConservative) {
            EXPECT_FALSE(lod::cullsPatch(lod::cullParams(policy, view, run.bounds()),
                                         run.bounds().patches[p]))
                << technique_id << " patch " << p << " " << lod::cullPolicyName(policy);
          }
        }
      }
    }
  }
  EXPECT_GT(straddling_seen, 20u);
}

// combined = frustum_hull or cone, tangent_plane_frustum = frustum_hull or tangent_plane,
// patch by patch on every view (CPU twin; the twin equals the TCS, cull_policy_test.cpp).
void expectUnionsOfHalves(const lod::CullBounds& bounds, std::span<const view::View> views,
                          const std::string& label) {
  using P = lod::CullPolicy;
  for (const view::View& view : views) {
    auto decide = [&](P policy) {
      return lod::cullDecisions(lod::cullParams(policy, view, bounds), bounds);
    };
    const std::vector<uint8_t> hull = decide(P::kFrustumHull), cone = decide(P::kCone),
                               tangent = decide(P::kTangentPlane), combined = decide(P::kCombined),
                               tangent_frustum = decide(P::kTangentPlaneFrustum);
    for (size_t p = 0; p < hull.size(); ++p) {
      ASSERT_EQ(combined[p], hull[p] | cone[p]) << label << " patch " << p;
      ASSERT_EQ(tangent_frustum[p], hull[p] | tangent[p]) << label << " patch " << p;
    }
  }
}

struct AssetCase {
  std::string technique;
  std::string asset;
};

std::vector<AssetCase> everyBundledAsset() {
  std::vector<AssetCase> cases;
  const std::filesystem::path root = testing::assetPath(".");
  std::vector<std::filesystem::path> files;
  for (const char* folder : {"opensubdiv", "tessbench"}) {
    for (const auto& entry : std::filesystem::directory_iterator(root / folder)) {
      if (entry.path().extension() == ".obj") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  // Under a sanitizer, every 4th asset of each technique, a different quarter per technique.
  const size_t stride = testing::sweepStride(4);
  size_t t = 0;
  for (const char* technique : {"acc", "gregory_acc", "pn_triangles", "phong"}) {
    for (size_t i = 0; i < files.size(); ++i) {
      if ((i + t) % stride == 0) cases.push_back({technique, files[i].string()});
    }
    ++t;
  }
  return cases;
}

// Acceptance 2: frustum_hull, cone and tangent_plane make no false cull on any bundled
// asset a technique accepts, along orbit (every frame), dolly and flyby (every third frame),
// at level 4 and 960 x 540; the twin equals the TCS throughout. combined and
// tangent_plane_frustum cull on each frame exactly the union of their halves' culls.
TEST(Culling, ConservativePoliciesMakeNoFalseCullOnAnyBundledAssetAndPath) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  size_t runs = 0, culled = 0;
  for (const AssetCase& c : everyBundledAsset()) {
    const techniques::Technique* technique =
        techniques::TechniqueRegistry::instance().find(c.technique);
    const mesh::Mesh mesh = mesh::loadObjFile(c.asset);
    if (!technique->checkSupport(mesh).empty()) continue;
    techniques::BuiltSurface patches;
    try {
      patches = techniques::buildSurface(*technique, mesh, technique->variants().front());
    } catch (const techniques::UnsupportedInput&) {
      continue;
    }
    measures::CullingRun run(*patches, &context, "", {.level = 4, .render_scale = 0.5});
    const mesh::Aabb box = mesh::boundsOf(patches->controlMesh());
    for (const char* path : {"orbit", "dolly", "flyby"}) {
      const view::CameraPath sampled =
          suite::sampleCameraPath(suite::resolveCameraPath(path), box, 0);
      std::vector<view::View> views;
      // Under a sanitizer a third of those frames.
      const size_t step = (std::string(path) == "orbit" ? 1 : 3) * testing::sweepStride(3);
      for (size_t f = 0; f < sampled.views.size(); f += step) views.push_back(sampled.views[f]);
      const auto frames = run.frames(kConservativeTests, views);
      expectUnionsOfHalves(run.bounds(), views, c.technique + " " + c.asset);
      for (size_t k = 0; k < std::size(kConservativeTests); ++k) {
        for (const measures::CullingFrame& f : frames[k]) {
          ASSERT_TRUE(f.oracle_measured) << run.gpuSkipReason();
          EXPECT_EQ(f.false_culls, 0u)
              << c.technique << " " << c.asset << " " << path << " frame " << f.frame * step << " "
              << lod::cullPolicyName(kConservativeTests[k]) << ": " << f.false_cull_pixels << " px";
          EXPECT_EQ(f.twin_mismatches, 0u) << c.technique << " " << c.asset;
          EXPECT_FALSE(f.gpu_tes_invocations != f.tes_invocations) << c.technique << " " << c.asset;
          culled += f.culled_patches;
        }
      }
    }
    ++runs;
  }
  EXPECT_GT(runs, 60u / testing::sweepStride(4));
  EXPECT_GT(culled, 0u);
}

// Acceptance 4, the control: tangent_plane with its coefficients' sign flipped (it culls
// the patches facing the eye) is caught by the false-cull check above on its first asset.
TEST(Culling, AFlippedTangentPlaneSignIsCaughtAsFalseCulls) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_torus.obj"));
  const techniques::BuiltSurface patches = buildDefault("acc", mesh);
  const std::vector<view::View> views = viewsFromAfar(mesh, 3);
  const lod::CullPolicy policy[] = {lod::CullPolicy::kTangentPlane};
  for (bool flip : {false, true}) {
    measures::CullingRun run(*patches, &context, "",
                             {.level = 16, .render_scale = 0.25, .flip_tangent_plane = flip});
    uint64_t false_culls = 0, culled = 0;
    const std::vector<std::vector<measures::CullingFrame>> frames = run.frames(policy, views);
    for (const measures::CullingFrame& f : frames[0]) {
      false_culls += f.false_culls;
      culled += f.culled_patches;
    }
    EXPECT_GT(culled, 0u) << "flip " << flip;
    if (flip) {
      EXPECT_GT(false_culls, 0u) << "the flipped sign culls patches facing the eye";
    } else {
      EXPECT_EQ(false_culls, 0u);
    }
  }
}

}  // namespace
}  // namespace tb
