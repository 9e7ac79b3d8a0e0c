#include "core/gpu/compute.h"

#include <cmath>
#include <limits>

#include "core/gpu/context.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

ComputePipeline::ComputePipeline(Context& context, std::span<const uint32_t> spirv,
                                 uint32_t storage_buffer_count, uint32_t push_constant_bytes)
    : context_(context),
      storage_buffer_count_(storage_buffer_count),
      push_constant_bytes_(push_constant_bytes) {
  context.requireFeatures(computeFeatures(), "compute pipeline");
  const VkDevice device = context.device();
  const std::vector<VkShaderStageFlags> stages(storage_buffer_count, VK_SHADER_STAGE_COMPUTE_BIT);
  set_layout_ = createStorageBufferSetLayout(device, stages);
  layout_ = createPipelineLayout(device, set_layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT,
                                 push_constant_bytes);
  const VkShaderModuleOwner module = createShaderModule(device, spirv);
  auto info = vkStruct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
  info.stage = shaderStage(VK_SHADER_STAGE_COMPUTE_BIT, module.get());
  info.layout = layout_.get();
  VkPipeline pipeline = VK_NULL_HANDLE;
  vkCheck(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
          "vkCreateComputePipelines");
  pipeline_ = VkPipelineOwner(device, pipeline);
  descriptors_ = StorageBufferSet(device, set_layout_.get(), storage_buffer_count);

  if (context.features().timestamps) {
    auto query_info = vkStruct<VkQueryPoolCreateInfo>(VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO);
    query_info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    query_info.queryCount = 2;
    VkQueryPool pool = VK_NULL_HANDLE;
    vkCheck(vkCreateQueryPool(device, &query_info, nullptr, &pool), "vkCreateQueryPool");
    timestamps_ = VkQueryPoolOwner(device, pool);
  }
}

ComputeTiming ComputePipeline::dispatch(std::span<const Buffer* const> buffers,
                                        std::span<const std::byte> push_constants,
                                        uint32_t groups_x, uint32_t groups_y, uint32_t groups_z) {
  if (buffers.size() != storage_buffer_count_ || push_constants.size() != push_constant_bytes_) {
    throw GpuError("ComputePipeline::dispatch: buffer count or push-constant size mismatch");
  }
  std::vector<VkBuffer> handles;
  for (const Buffer* buffer : buffers) handles.push_back(buffer->handle());
  descriptors_.bind(context_.device(), handles);
  const VkQueryPool timestamps = timestamps_.get();

  ComputeTiming timing;
  timing.submit_to_fence_s = context_.submitAndWait([&](VkCommandBuffer cmd) {
    if (timestamps) vkCmdResetQueryPool(cmd, timestamps, 0, 2);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
    const VkDescriptorSet set = descriptors_.set;
    if (storage_buffer_count_ > 0) {
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 1, &set, 0,
                              nullptr);
    }
    if (!push_constants.empty()) {
      vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                         static_cast<uint32_t>(push_constants.size()), push_constants.data());
    }
    if (timestamps) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps, 0);
    vkCmdDispatch(cmd, groups_x, groups_y, groups_z);
    if (timestamps) {
      vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps, 1);
    }
    auto barrier = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &barrier, 0, nullptr, 0, nullptr);
  });

  timing.gpu_ns = std::numeric_limits<double>::quiet_NaN();
  if (timestamps) {
    uint64_t ticks[2] = {0, 0};
    vkCheck(
        vkGetQueryPoolResults(context_.device(), timestamps, 0, 2, sizeof(ticks), ticks,
                              sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults (timestamps)");
    timing.gpu_ns = static_cast<double>(ticks[1] - ticks[0]) * context_.info().timestamp_period_ns;
  }
  return timing;
}

}  // namespace tb::gpu
