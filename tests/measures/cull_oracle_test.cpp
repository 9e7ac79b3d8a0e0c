// The culling measure's oracle (cull_oracle.h). Oracles: hand-made scenes of flat triangles
// (phong with flat normals leaves them flat) whose visibility is known by construction
// (behind the eye, off screen, facing the eye, facing away, straddling the screen edge,
// hidden behind another); the two halves agreeing on a closed convex surface (a patch with
// pixels is never ideally cullable); the CPU tessellator's triangle count per patch; and
// the winding convention (outside is front) per technique by the divergence theorem: on a
// closed surface seen from inside, sum(area vector . (centroid - centre)) > 0 per patch
// when triangles face out.
#include "harness/measures/culling/cull_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/gpu/gpu_error.h"
#include "core/mesh/obj_loader.h"
#include "core/view/camera.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/measures/face_patches.h"
#include "tests/test_support.h"

namespace tb {
namespace {

constexpr double kFovYRad = 60 * std::numbers::pi / 180;
constexpr uint32_t kWidth = 64, kHeight = 48;

view::View viewFrom(const mesh::Vec3d& eye, const mesh::Vec3d& target, uint32_t width_px,
                    uint32_t height_px) {
  return view::perspectiveView({.eye = eye,
                                .target = target,
                                .fov_y_rad = kFovYRad,
                                .width_px = width_px,
                                .height_px = height_px,
                                .near_plane = 0.1,
                                .far_plane = 100});
}

tess::Levels uniformLevels(float level) {
  tess::Levels levels;
  levels.outer = {level, level, level, level};
  levels.inner = {level, level};
  return levels;
}

techniques::BuiltSurface build(const std::string& technique_id, const mesh::Mesh& mesh) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  if (technique == nullptr) throw std::logic_error("no technique " + technique_id);
  return techniques::buildSurface(*technique, mesh, technique->variants()[0]);
}

// Separate flat triangles (one OBJ face each, every corner with the face's own normal),
// built with phong: a flat patch per triangle.
techniques::BuiltSurface flatTriangles(const std::vector<std::array<mesh::Vec3d, 3>>& triangles) {
  std::string obj;
  for (const auto& t : triangles) {
    for (const mesh::Vec3d& p : t) {
      obj +=
          "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
    const mesh::Vec3d n = normalize(cross(t[1] - t[0], t[2] - t[0]));
    obj +=
        "vn " + std::to_string(n.x) + " " + std::to_string(n.y) + " " + std::to_string(n.z) + "\n";
  }
  for (size_t f = 0; f < triangles.size(); ++f) {
    const std::string n = std::to_string(f + 1);
    obj += "f";
    for (size_t k = 1; k <= 3; ++k) {
      obj += ' ';
      obj += std::to_string(3 * f + k);
      obj += "//";
      obj += n;
    }
    obj += "\n";
  }
  return build("phong", mesh::loadObjText(obj, "flat_triangles"));
}

// The camera of the hand-made scenes: at z = 5 looking down -z; at z = 0 the screen spans
// |x| < 5 tan(30 deg) 4/3 = 3.85 and |y| < 2.89.
view::View sceneView() { return viewFrom({0, 0, 5}, {0, 0, 0}, kWidth, kHeight); }

TEST(CullOracle, HandMadeSceneSeparatesVisibleFromCullable) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface patches = flatTriangles({
      {{{-2.5, -1, 0}, {-0.5, -1, 0}, {-1.5, 1, 0}}},  // 0: facing the eye (normal +z)
      {{{0.5, -1, 0}, {1.5, 1, 0}, {2.5, -1, 0}}},     // 1: facing away (normal -z), on screen
      {{{-1, -1, 8}, {0, 1, 8}, {1, -1, 8}}},          // 2: behind the eye, normal towards it
      {{{10, -1, 0}, {12, -1, 0}, {11, 1, 0}}},        // 3: in front, right of the screen
  });
  const measures::DeviceSurface surface =
      measures::tessellateOnDevice(context, *patches, tess::Spacing::kInteger, uniformLevels(3));
  ASSERT_EQ(surface.patch_count, 4u);
  measures::VisibilityOracle oracle(context, surface);
  const measures::PatchVisibility v = oracle.visibility(sceneView());
  ASSERT_EQ(v.visible_pixels.size(), 4u);
  ASSERT_EQ(v.ideally_cullable.size(), 4u);
  EXPECT_GT(v.visible_pixels[0], 50u);  // about 1/10 of the 64 x 48 image
  for (size_t p = 1; p < 4; ++p) EXPECT_EQ(v.visible_pixels[p], 0u) << p;
  EXPECT_EQ(v.ideally_cullable, (std::vector<uint8_t>{0, 1, 1, 1}));
  // By cause: 1 faces away inside the frustum; 2 (behind the eye) and 3 lie outside it.
  ASSERT_EQ(v.back_facing.size(), 4u);
  EXPECT_EQ(v.back_facing[0], 0);
  EXPECT_EQ(v.back_facing[1], 1);
  EXPECT_EQ(v.back_facing[3], 0);
  EXPECT_EQ(v.outside_frustum, (std::vector<uint8_t>{0, 0, 1, 1}));
}

TEST(CullOracle, StraddlingPatchIsVisibleAndOccludedPatchIsNotCullable) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface patches = flatTriangles({
      {{{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}}},               // 0: the occluder, facing the eye
      {{{-0.3, -0.3, -1}, {0.3, -0.3, -1}, {0, 0.3, -1}}},  // 1: facing the eye, behind 0
      {{{3, -1, 0}, {5, -1, 0}, {4, 1, 0}}},                // 2: across the right edge (x = 3.85)
  });
  const measures::DeviceSurface surface =
      measures::tessellateOnDevice(context, *patches, tess::Spacing::kInteger, uniformLevels(2));
  measures::VisibilityOracle oracle(context, surface);
  const measures::PatchVisibility v = oracle.visibility(sceneView());
  EXPECT_GT(v.visible_pixels[0], 0u);
  EXPECT_EQ(v.visible_pixels[1], 0u);
  EXPECT_GT(v.visible_pixels[2], 0u);
  EXPECT_EQ(v.ideally_cullable, (std::vector<uint8_t>{0, 0, 0}));

  // Without the occluder, patch 1 shows: it was hidden, not missed.
  const techniques::BuiltSurface alone =
      flatTriangles({{{{-0.3, -0.3, -1}, {0.3, -0.3, -1}, {0, 0.3, -1}}}});
  measures::VisibilityOracle alone_oracle(
      context,
      measures::tessellateOnDevice(context, *alone, tess::Spacing::kInteger, uniformLevels(2)));
  EXPECT_GT(alone_oracle.visibility(sceneView()).visible_pixels[0], 0u);
}

TEST(CullOracle, ConvexSurfaceHalvesAgreeAndRenderTargetIsReusedAcrossSizes) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface patches =
      build("acc", mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_cube.obj")));
  measures::VisibilityOracle oracle(
      context,
      measures::tessellateOnDevice(context, *patches, tess::Spacing::kInteger, uniformLevels(6)));
  // On the +z axis (the -z patch faces away everywhere), from a corner, and from the corner
  // again at another size (a new render target), then at the first size again.
  const std::vector<view::View> views = {
      viewFrom({0.2, 0.3, 4}, {0, 0, 0}, kWidth, kHeight),
      viewFrom({2.5, 2, 3}, {0, 0, 0}, kWidth, kHeight),
      viewFrom({2.5, 2, 3}, {0, 0, 0}, 96, 40),
      viewFrom({0.2, 0.3, 4}, {0, 0, 0}, kWidth, kHeight),
  };
  std::vector<measures::PatchVisibility> results;
  for (const view::View& view : views) {
    const measures::PatchVisibility v = oracle.visibility(view);
    uint64_t visible = 0, total = 0, cullable = 0;
    for (size_t p = 0; p < v.visible_pixels.size(); ++p) {
      total += v.visible_pixels[p];
      visible += v.visible_pixels[p] > 0;
      cullable += v.ideally_cullable[p];
      if (v.visible_pixels[p] > 0) {
        EXPECT_EQ(v.ideally_cullable[p], 0) << "patch " << p;
      }
    }
    EXPECT_GE(visible, 1u);
    EXPECT_GE(cullable, 1u);
    EXPECT_LE(total, uint64_t{view.viewport_width_px} * view.viewport_height_px);
    results.push_back(v);
  }
  EXPECT_EQ(results[0].visible_pixels, results[3].visible_pixels);
  EXPECT_EQ(results[0].ideally_cullable, results[3].ideally_cullable);
}

TEST(CullOracle, DeviceSurfaceHasTheTessellatorsTrianglesPerPatch) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  // Mixed quads and triangle patches (two programs with patch_ids), fractional levels.
  const techniques::BuiltSurface patches =
      build("gregory_acc", mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_pyramid.obj")));
  const tess::Levels levels = uniformLevels(5.5f);
  for (tess::Spacing spacing : {tess::Spacing::kInteger, tess::Spacing::kPow2,
                                tess::Spacing::kFractionalOdd, tess::Spacing::kFractionalEven}) {
    SCOPED_TRACE(tess::toString(spacing));
    const measures::DeviceSurface surface =
        measures::tessellateOnDevice(context, *patches, spacing, levels);
    ASSERT_EQ(surface.patch_count, patches->patchCount());
    ASSERT_EQ(surface.triangle_patch.size(), surface.triangles.size());
    std::vector<size_t> per_patch(surface.patch_count, 0);
    for (uint32_t patch : surface.triangle_patch) ++per_patch.at(patch);
    bool both_domains[2] = {false, false};
    for (size_t p = 0; p < surface.patch_count; ++p) {
      const bool quad = patches->patchDomain(p) == techniques::PatchDomain::kQuad;
      both_domains[quad] = true;
      const tess::Domain domain = quad ? tess::Domain::kQuad : tess::Domain::kTriangle;
      EXPECT_EQ(per_patch[p], tess::tessellate(domain, spacing, levels).triangles.size()) << p;
    }
    EXPECT_TRUE(both_domains[0] && both_domains[1]);
  }
}

class NoProgramPatches final : public testing::FacePatches {
 public:
  using FacePatches::FacePatches;
  techniques::SurfacePoint evaluate(size_t, const techniques::DomainCoord&) const override {
    return {};
  }
  techniques::SurfacePointF evaluateFloat(size_t, const tess::DomainPoint&) const override {
    return {};
  }
};

TEST(CullOracle, TessellateOnDeviceRefusesATechniqueWithoutGpuProgram) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  mesh::Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const uint32_t face[] = {0, 1, 2};
  mesh.addFace(face, {}, {}, 0);
  const NoProgramPatches patches(mesh);
  EXPECT_THROW(
      measures::tessellateOnDevice(context, patches, tess::Spacing::kInteger, uniformLevels(2)),
      gpu::GpuError);
}

// Outside is front for every technique: per patch, the tessellated triangles' area vectors
// point away from the centre of a closed convex mesh.
TEST(CullOracle, EveryTechniquesTrianglesFaceOutOfAClosedConvexMesh) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"acc", "catmark_cube"},
      {"gregory_acc", "catmark_cube"},
      {"gregory_acc", "catmark_pyramid"},  // quads and triangles: two programs
      {"gregory_acc", "loop_cube"},
      {"gregory_acc", "loop_icosahedron"},
      {"pn_triangles", "catmark_cube"},
      {"pn_triangles", "loop_cube"},
      {"pn_triangles", "loop_icosahedron"},
      {"phong", "catmark_cube"},
      {"phong", "loop_cube"},
      {"phong", "loop_icosahedron"},
  };
  for (const auto& [technique, asset] : cases) {
    SCOPED_TRACE(technique + " on " + asset);
    const mesh::Mesh mesh = mesh::loadObjFile(testing::assetPath("opensubdiv/" + asset + ".obj"));
    const techniques::BuiltSurface patches = build(technique, mesh);
    mesh::Vec3d centre{};
    for (const mesh::Vec3d& p : mesh.positions) centre = centre + p;
    centre = centre * (1.0 / double(mesh.positions.size()));
    const measures::DeviceSurface surface =
        measures::tessellateOnDevice(context, *patches, tess::Spacing::kInteger, uniformLevels(4));
    std::vector<double> outward(surface.patch_count, 0);
    for (size_t t = 0; t < surface.triangles.size(); ++t) {
      const mesh::Vec3d a = vecCast<double>(surface.triangles[t][0]);
      const mesh::Vec3d b = vecCast<double>(surface.triangles[t][1]);
      const mesh::Vec3d c = vecCast<double>(surface.triangles[t][2]);
      const mesh::Vec3d area = cross(b - a, c - a) * 0.5;
      outward[surface.triangle_patch[t]] += dot(area, (a + b + c) * (1.0 / 3) - centre);
    }
    for (size_t p = 0; p < outward.size(); ++p) EXPECT_GT(outward[p], 0) << "patch " << p;
  }
}

}  // namespace
}  // namespace tb
