// Oracles: ACC is exact on an all-regular Catmull-Clark mesh (catmark_torus: every vertex
// of valence 4, so each patch is the bicubic B-spline Bfr evaluates; error ~1e-16 of the
// diagonal), so every covered pixel of its error picture has the ramp's first colour; PN
// triangles on the coarse loop_cube are far from the Loop limit (~1e-2), so the upper half
// of the ramp shows. lavapipe's ID buffer says which pixels are covered. Skips without a
// Vulkan device.
#include "harness/pictures/surface_picture.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/gpu/render_target.h"
#include "core/mesh/obj_loader.h"
#include "harness/pictures/heat_map.h"
#include "harness/pictures/png_writer.h"
#include "techniques/registry.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/test_support.h"

namespace tb {
namespace {

techniques::BuiltSurface defaultSurface(const char* technique_id, const char* asset) {
  const techniques::Technique* technique =
      techniques::TechniqueRegistry::instance().find(technique_id);
  if (technique == nullptr) return {};
  return techniques::buildSurface(*technique, mesh::loadObjFile(testing::assetPath(asset)),
                                  technique->variants().front());
}

// Whether the pixel is the ramp colour `base` under some shading factor in [0.45, 1]
// (surface_picture.cpp's Lambert range), up to rounding.
bool isShadedFrom(pictures::Rgb pixel, pictures::Rgb base) {
  for (int f = 45; f <= 100; ++f) {
    auto close = [&](uint8_t p, uint8_t b) { return std::abs(int(p) - b * f / 100.0) <= 1.5; };
    if (close(pixel.r, base.r) && close(pixel.g, base.g) && close(pixel.b, base.b)) return true;
  }
  return false;
}

TEST(SurfacePicture, AnExactSurfaceIsAllTheRampsLowEnd) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface acc = defaultSurface("acc", "opensubdiv/catmark_torus.obj");
  ASSERT_TRUE(acc);
  const pictures::SurfacePictures pictures =
      pictures::renderSurfacePictures(context, *acc, {8, 160});
  EXPECT_LT(pictures.error_max, 1e-12);
  EXPECT_EQ(pictures.scale_max, pictures::kMinimumScaleMax);
  ASSERT_GT(pictures.covered_pixels, 160u * 160u / 10);
  uint64_t low = 0;
  for (uint32_t y = 0; y < 160; ++y) {
    for (uint32_t x = 0; x < 160; ++x) {
      const bool covered = pictures.triangle_ids[y * 160 + x] != gpu::RenderTarget::kNoId;
      const pictures::Rgb pixel = pictures.error.at(x, y);
      if (!covered) {
        EXPECT_EQ(pixel, pictures::kWhite);
        continue;
      }
      low += isShadedFrom(pixel, pictures::heatColourLow());
    }
  }
  EXPECT_EQ(low, pictures.covered_pixels);
}

TEST(SurfacePicture, AnInexactSurfaceReachesTheRampsHighEnd) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface pn = defaultSurface("pn_triangles", "opensubdiv/loop_cube.obj");
  ASSERT_TRUE(pn);
  const pictures::SurfacePictures pictures =
      pictures::renderSurfacePictures(context, *pn, {8, 160});
  EXPECT_GT(pictures.error_max, 1e-3);
  EXPECT_EQ(pictures.scale_max, pictures.error_max);
  ASSERT_GT(pictures.covered_pixels, 160u * 160u / 10);
  uint64_t low = 0, upper_half = 0;
  for (uint32_t y = 0; y < 160; ++y) {
    for (uint32_t x = 0; x < 160; ++x) {
      if (pictures.triangle_ids[y * 160 + x] == gpu::RenderTarget::kNoId) continue;
      const pictures::Rgb pixel = pictures.error.at(x, y);
      low += isShadedFrom(pixel, pictures::heatColourLow());
      // Green above 100 only comes from the upper half of the ramp (heat_map.cpp).
      upper_half += pixel.g > 100;
    }
  }
  EXPECT_LT(low, pictures.covered_pixels);
  EXPECT_GT(upper_half, 0u);
}

TEST(SurfacePicture, TheWireframeHasMoreLinesAtAHigherLevel) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface acc = defaultSurface("acc", "opensubdiv/catmark_torus.obj");
  ASSERT_TRUE(acc);
  const pictures::SurfacePictures coarse = pictures::renderSurfacePictures(context, *acc, {2, 320});
  const pictures::SurfacePictures fine = pictures::renderSurfacePictures(context, *acc, {8, 320});
  EXPECT_GT(coarse.edge_pixels, 0u);
  EXPECT_LT(coarse.edge_pixels, coarse.covered_pixels);
  EXPECT_GT(fine.edge_pixels, coarse.edge_pixels * 2);
  // The lines are the dark pixels of the wireframe picture.
  uint64_t dark = 0;
  for (uint32_t y = 0; y < 320; ++y) {
    for (uint32_t x = 0; x < 320; ++x) dark += fine.wireframe.at(x, y) == pictures::Rgb{30, 30, 30};
  }
  EXPECT_EQ(dark, fine.edge_pixels);
}

TEST(SurfacePicture, TwoRendersAreByteIdentical) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const techniques::BuiltSurface gregory =
      defaultSurface("gregory_acc", "opensubdiv/catmark_nonquads.obj");
  ASSERT_TRUE(gregory);
  const pictures::SurfacePictures first =
      pictures::renderSurfacePictures(context, *gregory, {8, 200});
  const pictures::SurfacePictures second =
      pictures::renderSurfacePictures(context, *gregory, {8, 200});
  EXPECT_EQ(first.triangle_ids, second.triangle_ids);
  EXPECT_EQ(pictures::encodePng(first.error), pictures::encodePng(second.error));
  EXPECT_EQ(pictures::encodePng(first.wireframe), pictures::encodePng(second.wireframe));
  EXPECT_EQ(first.error.width_px, 200u);
  EXPECT_EQ(first.error.height_px, 200u + pictures::kColourBarStripPx);
}

TEST(SurfacePicture, TheCameraSeesTheWholeBox) {
  const mesh::Aabb box{{-1, 2, 0}, {3, 4, 10}};
  const view::View view = pictures::threeQuarterView(box, 100);
  for (int corner = 0; corner < 8; ++corner) {
    const mesh::Vec3d p{corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                        corner & 4 ? box.max.z : box.min.z};
    const auto c = view.view_projection.transform({p.x, p.y, p.z, 1});
    ASSERT_GT(c[3], 0);
    EXPECT_LE(std::abs(c[0]), c[3]);
    EXPECT_LE(std::abs(c[1]), c[3]);
    EXPECT_GE(c[2], 0);
    EXPECT_LE(c[2], c[3]);
  }
  EXPECT_THROW(pictures::threeQuarterView(mesh::Aabb{{1, 1, 1}, {1, 1, 1}}, 100),
               std::invalid_argument);
}

}  // namespace
}  // namespace tb
