// The ID render target. Oracle: the Vulkan rasterization rules (a pixel is covered when
// its centre is inside the triangle; top-left rule on edges), checked away from edges.
#include "core/gpu/render_target.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "core/mesh/vec.h"
#include "core/view/camera.h"
#include "tests/gpu/gpu_test_support.h"

namespace tb::gpu {
namespace {

constexpr uint32_t kSize = 64;

TEST(RenderTarget, OneTriangleCoversTheExpectedPixelsWithItsId) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  RenderTarget target(context, kSize, kSize);
  // Clip (-1,-1), (1,-1), (-1,1): the top-left half, pixels with x + y + 1 < 64 (centres).
  const std::vector<std::array<float, 4>> positions = {
      {-1, -1, 0.5f, 1}, {1, -1, 0.5f, 1}, {-1, 1, 0.5f, 1}};
  const std::vector<uint32_t> ids = {7};
  target.drawTriangles(positions, ids);

  const std::vector<uint32_t> id = target.ids();
  const std::vector<float> depth = target.depths();
  ASSERT_EQ(id.size(), kSize * kSize);
  uint32_t covered = 0;
  for (uint32_t y = 0; y < kSize; ++y) {
    for (uint32_t x = 0; x < kSize; ++x) {
      const uint32_t value = id[y * kSize + x];
      covered += value == 7;
      if (x + y + 1 < kSize) {
        EXPECT_EQ(value, 7u) << x << "," << y;
        EXPECT_EQ(depth[y * kSize + x], 0.5f);
      } else if (x + y + 1 > kSize) {
        EXPECT_EQ(value, RenderTarget::kNoId) << x << "," << y;
        EXPECT_EQ(depth[y * kSize + x], 1.0f);
      }
    }
  }
  // Strictly inside: 64*63/2 = 2016 pixels; the diagonal's 64 centres lie on the edge.
  EXPECT_GE(covered, 2016u);
  EXPECT_LE(covered, 2016u + kSize);
  EXPECT_NE(target.colors()[0], 0u);
  EXPECT_EQ(target.colors()[kSize * kSize - 1], 0u);
}

TEST(RenderTarget, NearerTriangleWinsTheDepthTest) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  RenderTarget target(context, kSize, kSize);
  const std::vector<std::array<float, 4>> positions = {
      {-1, -1, 0.2f, 1}, {3, -1, 0.2f, 1}, {-1, 3, 0.2f, 1},   // full screen, near
      {-1, -1, 0.8f, 1}, {3, -1, 0.8f, 1}, {-1, 3, 0.8f, 1}};  // full screen, far, drawn last
  const std::vector<uint32_t> ids = {1, 2};
  target.drawTriangles(positions, ids);
  for (uint32_t value : target.ids()) ASSERT_EQ(value, 1u);
}

uint32_t countId(std::span<const uint32_t> ids, uint32_t wanted) {
  return uint32_t(std::count(ids.begin(), ids.end(), wanted));
}

// Full-screen triangles: clip (-1,-1), (3,-1), (-1,3) is clockwise on the image (top-left,
// top-right, bottom-left with y down) and det[x y w] = 16 > 0; the reverse order is
// counter-clockwise, det < 0.
const std::vector<std::array<float, 4>> kClockwise = {
    {-1, -1, 0.5f, 1}, {3, -1, 0.5f, 1}, {-1, 3, 0.5f, 1}};
const std::vector<std::array<float, 4>> kCounterClockwise = {
    {-1, -1, 0.5f, 1}, {-1, 3, 0.5f, 1}, {3, -1, 0.5f, 1}};

TEST(RenderTarget, BackFaceCullingDropsClockwiseTrianglesOnly) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  RenderTarget target(context, kSize, kSize);
  const std::vector<uint32_t> ids = {5};
  RenderTarget::DrawOptions cull;
  cull.cull_back_faces = true;

  target.drawTriangles(kClockwise, ids);  // default: no culling
  EXPECT_EQ(countId(target.mappedIds(), 5), kSize * kSize);
  target.drawTriangles(kClockwise, ids, cull);
  EXPECT_EQ(countId(target.mappedIds(), 5), 0u);
  target.drawTriangles(kCounterClockwise, ids, cull);
  EXPECT_EQ(countId(target.mappedIds(), 5), kSize * kSize);
}

// The convention in world terms: with core/view/camera.h's matrices (y flipped into clip
// space, so the image is upright), a triangle counter-clockwise seen from the eye (its
// normal (v1 - v0) x (v2 - v0) towards the eye) is front-facing; its mirror is culled.
TEST(RenderTarget, WorldTriangleFacingTheEyeIsFrontFacing) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  const view::Mat4 view_projection =
      view::perspective(1.0, 1.0, 0.1, 10.0) * view::lookAt({0.3, -0.2, 4}, {0, 0, 0}, {0, 1, 0});
  auto clip = [&](const mesh::Vec3d& p) {
    const auto c = view_projection.transform({p.x, p.y, p.z, 1});
    return std::array<float, 4>{float(c[0]), float(c[1]), float(c[2]), float(c[3])};
  };
  const mesh::Vec3d a{-1, -1, 0}, b{1, -1, 0}, c{0, 1, 0};  // normal +z, towards the eye
  ASSERT_GT(cross(b - a, c - a).z, 0);
  RenderTarget target(context, kSize, kSize);
  RenderTarget::DrawOptions cull;
  cull.cull_back_faces = true;
  const std::vector<uint32_t> ids = {9};
  const std::vector<std::array<float, 4>> facing = {clip(a), clip(b), clip(c)};
  target.drawTriangles(facing, ids, cull);
  EXPECT_GT(countId(target.mappedIds(), 9), 0u);
  const std::vector<std::array<float, 4>> away = {clip(a), clip(c), clip(b)};
  target.drawTriangles(away, ids, cull);
  EXPECT_EQ(countId(target.mappedIds(), 9), 0u);
}

TEST(RenderTarget, IdsOnlyReadbackKeepsIdsAndRefusesColoursAndDepths) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  RenderTarget target(context, kSize, kSize);
  const std::vector<uint32_t> ids = {3};
  target.drawTriangles(kCounterClockwise, ids);
  const std::vector<uint32_t> all_ids = target.ids();
  RenderTarget::DrawOptions ids_only;
  ids_only.readback = RenderTarget::Readback::kIdsOnly;
  target.drawTriangles(kCounterClockwise, ids, ids_only);
  const std::span<const uint32_t> in_place = target.mappedIds();
  EXPECT_TRUE(std::equal(in_place.begin(), in_place.end(), all_ids.begin(), all_ids.end()));
  EXPECT_THROW(target.colors(), GpuError);
  EXPECT_THROW(target.depths(), GpuError);
}

}  // namespace
}  // namespace tb::gpu
