// The ID render target. Oracle: the Vulkan rasterization rules (a pixel is covered when
// its centre is inside the triangle; top-left rule on edges), checked away from edges.
#include "core/gpu/render_target.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

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

}  // namespace
}  // namespace tb::gpu
