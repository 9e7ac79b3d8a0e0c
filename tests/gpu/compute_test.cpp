// The compute path end to end. Oracle: the same arithmetic on the host (x * 2 is exact).
#include "core/gpu/compute.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/gpu/pipeline_util.h"
#include "tests/gpu/gpu_test_support.h"

namespace tb::gpu {
namespace {

struct ScaleParams {
  uint32_t count;
  float factor;
};

TEST(Compute, ScaleBufferDoublesEveryElement) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  constexpr uint32_t kCount = 1000;  // not a multiple of the 64-wide group: tests the guard
  std::vector<float> input(kCount + 8);
  for (size_t i = 0; i < input.size(); ++i) input[i] = 0.25f * float(i) - 17.0f;
  Buffer data(context, input.size() * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  data.write(input.data(), input.size() * sizeof(float));

  ComputePipeline pipeline(context, requireEmbeddedShader("gpu/scale_buffer.comp"), 1,
                           sizeof(ScaleParams));
  const Buffer* buffers[] = {&data};
  const ComputeTiming timing =
      pipeline.dispatch(buffers, ScaleParams{kCount, 2.0f}, (kCount + 63) / 64);

  const auto output = data.as<float>();
  for (uint32_t i = 0; i < kCount; ++i) ASSERT_EQ(output[i], 2.0f * input[i]) << i;
  for (size_t i = kCount; i < input.size(); ++i) EXPECT_EQ(output[i], input[i]) << "untouched";
  EXPECT_GT(timing.submit_to_fence_s, 0.0);
  if (context.features().timestamps) {
    EXPECT_FALSE(std::isnan(timing.gpu_ns));
    EXPECT_GE(timing.gpu_ns, 0.0);
  }
}

TEST(Compute, MismatchedArgumentsThrowInsteadOfCrashing) {
  TB_GPU_CONTEXT_OR_SKIP(context);
  ComputePipeline pipeline(context, requireEmbeddedShader("gpu/scale_buffer.comp"), 1,
                           sizeof(ScaleParams));
  EXPECT_THROW(pipeline.dispatch({}, ScaleParams{1, 2.0f}, 1), GpuError);
}

}  // namespace
}  // namespace tb::gpu
