// A 2-D image shaders read with texelFetch (the displacement map of a "#displaced" patch
// program), and the descriptor set that binds it with the displacement's per-patch words
// (set 2 of shaders/common/displace.glsl).
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>

#include "core/gpu/buffer.h"
#include "core/gpu/device_image.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

class Context;

// The sampleable format of `channels` (1 or 4) float channels of `bytes_per_channel` (2 or
// 4) bytes: R16/R32 or R16G16B16A16/R32G32B32A32 SFLOAT. Throws GpuError otherwise.
VkFormat floatImageFormat(uint32_t channels, uint32_t bytes_per_channel);

class SampledImage {
 public:
  // Uploads `texels` (width * height texels of `format`, rows from the top, packed) through a
  // staging buffer and leaves the image in SHADER_READ_ONLY_OPTIMAL with a nearest,
  // clamp-to-edge sampler. Throws GpuError when the device cannot sample the format or the
  // byte count does not match.
  SampledImage(Context& context, VkFormat format, uint32_t width, uint32_t height,
               std::span<const std::byte> texels);
  VkImageView view() const { return image_.view.get(); }
  VkSampler sampler() const { return sampler_.get(); }

 private:
  DeviceImage image_;
  VkSamplerOwner sampler_;
};

// Set layout: binding 0 a combined image sampler, binding 1 a storage buffer, both read by
// the tessellation evaluation stage.
VkDescriptorSetLayoutOwner createDisplacementSetLayout(VkDevice device);

// One set of that layout with its own pool.
struct DisplacementSet {
  DisplacementSet() = default;
  DisplacementSet(VkDevice device, VkDescriptorSetLayout layout, const SampledImage& image,
                  const Buffer& patch_words);
  VkDescriptorPoolOwner pool;
  VkDescriptorSet set = VK_NULL_HANDLE;
};

}  // namespace tb::gpu
