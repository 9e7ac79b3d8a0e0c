// Every GPU path under VK_LAYER_KHRONOS_validation must report no error. Oracle: the
// validation layer itself. Without the layer installed the count is trivially 0 and the
// test says so.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "core/gpu/compute.h"
#include "core/gpu/render_target.h"
#include "core/gpu/tess_capture.h"
#include "tests/gpu/gpu_test_support.h"

namespace tb::gpu {
namespace {

// A fresh context with the layer requested (the shared one follows the build type).
class Validation : public ::testing::Test {
 protected:
  void SetUp() override {
    ContextOptions options;
    options.validation = ::tb::gpu::Validation::kOn;
    auto created = Context::create(options);
    if (!created) GTEST_SKIP() << "no usable Vulkan device: " << created.error();
    context_ = std::move(created.value());
  }
  std::unique_ptr<Context> context_;
};

TEST_F(Validation, NoValidationErrorsOnEveryPath) {
  Context& context = *context_;
  if (!context.info().validation_enabled) {
    std::printf("VK_LAYER_KHRONOS_validation is not installed: error count is trivially 0\n");
  }

  tess::Options point_mode;
  point_mode.point_mode = true;
  const tess::Levels levels{{3, 4.5f, 6, 2}, {5, 2.5f}};
  for (tess::Domain domain :
       {tess::Domain::kTriangle, tess::Domain::kQuad, tess::Domain::kIsoline}) {
    tessellateOnGpu(context, domain, tess::Spacing::kFractionalOdd, levels);
    tessellateOnGpu(context, domain, tess::Spacing::kPow2, levels, point_mode);
  }
  measureTessThroughput(context, tess::Domain::kQuad, tess::Spacing::kInteger, levels, 4);

  Buffer data(context, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  ComputePipeline compute(context, requireEmbeddedShader("gpu/scale_buffer.comp"), 1, 8);
  const Buffer* buffers[] = {&data};
  const struct {
    uint32_t count;
    float factor;
  } params{64, 3.0f};
  compute.dispatch(buffers, params, 1);

  RenderTarget target(context, 16, 16);
  const std::vector<std::array<float, 4>> positions = {
      {-1, -1, 0, 1}, {1, -1, 0, 1}, {-1, 1, 0, 1}};
  const std::vector<uint32_t> ids = {3};
  target.drawTriangles(positions, ids);
  RenderTarget::DrawOptions culled_ids_only;  // the culling oracle's draw
  culled_ids_only.cull_back_faces = true;
  culled_ids_only.readback = RenderTarget::Readback::kIdsOnly;
  target.drawTriangles(positions, ids, culled_ids_only);

  EXPECT_EQ(context.validationErrorCount(), 0u);
  TB_GPU_CONTEXT_OR_SKIP(shared);
  EXPECT_EQ(shared.validationErrorCount(), 0u);
}

// The counter itself: a buffer with no usage bits breaks VUID-VkBufferCreateInfo-usage-
// requiredbitmask, which the layer reports and lavapipe tolerates.
TEST_F(Validation, CountsADeliberateError) {
  Context& context = *context_;
  if (!context.info().validation_enabled) {
    GTEST_SKIP() << "VK_LAYER_KHRONOS_validation is not installed";
  }
  auto info = vkStruct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = 64;
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(context.device(), &info, nullptr, &buffer) == VK_SUCCESS) {
    vkDestroyBuffer(context.device(), buffer, nullptr);
  }
  EXPECT_GE(context.validationErrorCount(), 1u);
}

}  // namespace
}  // namespace tb::gpu
