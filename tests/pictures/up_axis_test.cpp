// Oracles: the shapes' own symmetry (a pawn is a surface of revolution about z in
// catmark_pawn.obj, a torus about y) and, for the pictures, the rendered silhouette: a
// standing pawn is taller than wide. Control: the same pawn under the y-up camera lies on
// its side (wider than tall), so the check can fail.
#include "harness/pictures/up_axis.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/gpu/render_target.h"
#include "core/mesh/obj_loader.h"
#include "harness/lod/reference_scheme.h"
#include "harness/measures/error/error.h"
#include "harness/pictures/surface_picture.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

std::vector<mesh::Vec3d> positionsOf(const char* asset) {
  return mesh::loadObjFile(testing::assetPath(asset)).positions;
}

TEST(UpAxis, SymmetryAboutZMeansZUp) {
  using pictures::UpAxis;
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("opensubdiv/catmark_pawn.obj")), UpAxis::kZ);
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("tessbench/tri_pawn.obj")), UpAxis::kZ);
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("opensubdiv/catmark_pyramid.obj")), UpAxis::kZ);
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("tessbench/cylinder_seam.obj")), UpAxis::kZ);
  // A cube turned 45 degrees about z: its variance is the same along every axis, its box not.
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("opensubdiv/catmark_cube.obj")), UpAxis::kZ);
  // Control: y-up and symmetric shapes keep y.
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("opensubdiv/catmark_torus.obj")), UpAxis::kY);
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("opensubdiv/loop_cube.obj")), UpAxis::kY);
  EXPECT_EQ(pictures::detectUpAxis(positionsOf("opensubdiv/catmark_chaikin0.obj")), UpAxis::kY);
  // The pawn turned to y-up is y-up.
  std::vector<mesh::Vec3d> turned = positionsOf("opensubdiv/catmark_pawn.obj");
  for (mesh::Vec3d& p : turned) p = {p.x, p.z, -p.y};
  EXPECT_EQ(pictures::detectUpAxis(turned), UpAxis::kY);
  EXPECT_EQ(pictures::detectUpAxis({}), UpAxis::kY);
  EXPECT_STREQ(pictures::toString(UpAxis::kZ), "z");
}

// Width and height (pixels) of the covered part of an ID buffer.
std::pair<uint32_t, uint32_t> coveredExtent(const std::vector<uint32_t>& ids, uint32_t size) {
  uint32_t x0 = size, x1 = 0, y0 = size, y1 = 0;
  for (uint32_t y = 0; y < size; ++y) {
    for (uint32_t x = 0; x < size; ++x) {
      if (ids[size_t(y) * size + x] == gpu::RenderTarget::kNoId) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  return x1 < x0 ? std::pair{0u, 0u} : std::pair{x1 - x0 + 1, y1 - y0 + 1};
}

TEST(UpAxis, AZUpPawnsPictureStandsUpright) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::Technique* phong = techniques::TechniqueRegistry::instance().find("phong");
  ASSERT_NE(phong, nullptr);
  const techniques::BuiltSurface surface = techniques::buildSurface(
      *phong, mesh::loadObjFile(testing::assetPath("opensubdiv/catmark_pawn.obj")),
      phong->variants().front());
  ASSERT_TRUE(surface);
  constexpr uint32_t kSize = 128;
  const pictures::SurfacePictures upright =
      pictures::renderSurfacePictures(context, *surface, {4, kSize});
  const auto [width, height] = coveredExtent(upright.triangle_ids, kSize);
  EXPECT_GT(height, width * 5 / 4) << width << " x " << height;
  // Control: the y-up camera on the same tessellation shows it lying down.
  const ref::LimitSurface limit(surface->controlMesh(),
                                lod::referenceScheme(surface->approximates()));
  const pictures::SurfaceErrorMesh mesh = pictures::tessellateWithError(*surface, limit, 4);
  gpu::RenderTarget target(context, kSize, kSize);
  const std::vector<uint32_t> lying = pictures::renderTriangleIds(
      target, mesh, pictures::threeQuarterView(mesh.bounds, kSize, pictures::UpAxis::kY));
  const auto [lying_width, lying_height] = coveredExtent(lying, kSize);
  EXPECT_LT(lying_height, lying_width) << lying_width << " x " << lying_height;
}

}  // namespace
}  // namespace tb
