// A compute pipeline over storage buffers and push constants, dispatched synchronously,
// timed both by GPU timestamps (fine for compute, also on lavapipe) and by the host.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/gpu/buffer.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

class Context;

struct ComputeTiming {
  double gpu_ns = 0;             // timestamp delta around the dispatch; NaN without timestamps
  double submit_to_fence_s = 0;  // host seconds, submit to fence
};

class ComputePipeline {
 public:
  // Binding i of set 0 is storage buffer i, for i < storage_buffer_count; push constants
  // are push_constant_bytes from offset 0. Throws GpuError on failure.
  ComputePipeline(Context& context, std::span<const uint32_t> spirv, uint32_t storage_buffer_count,
                  uint32_t push_constant_bytes);

  // Binds `buffers` to bindings 0.., pushes `push_constants`, dispatches groups, waits,
  // and makes the buffers' contents visible to the host.
  ComputeTiming dispatch(std::span<const Buffer* const> buffers,
                         std::span<const std::byte> push_constants, uint32_t groups_x,
                         uint32_t groups_y = 1, uint32_t groups_z = 1);

  template <class PushConstants>
  ComputeTiming dispatch(std::span<const Buffer* const> buffers, const PushConstants& push,
                         uint32_t groups_x, uint32_t groups_y = 1, uint32_t groups_z = 1) {
    return dispatch(buffers, std::as_bytes(std::span(&push, 1)), groups_x, groups_y, groups_z);
  }

 private:
  Context& context_;
  uint32_t storage_buffer_count_;
  uint32_t push_constant_bytes_;
  VkDescriptorSetLayoutOwner set_layout_;
  VkPipelineLayoutOwner layout_;
  VkPipelineOwner pipeline_;
  StorageBufferSet descriptors_;
  VkQueryPoolOwner timestamps_;  // empty when the queue has no timestamps
};

}  // namespace tb::gpu
