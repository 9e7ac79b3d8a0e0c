// A 2-D device-local image with its memory and a view, and the layout-transition barrier,
// shared by the render target's attachments and the sampled displacement maps.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>

#include "core/gpu/vk_handle.h"

namespace tb::gpu {

class Context;

struct DeviceImage {
  VkMemoryOwner memory;  // first, so it is freed after the image and view
  VkImageOwner image;
  VkImageViewOwner view;
};

// One mip level, one layer, optimal tiling, initial layout UNDEFINED. Throws GpuError when a
// Vulkan call fails.
DeviceImage createDeviceImage(Context& context, uint32_t width, uint32_t height, VkFormat format,
                              VkImageUsageFlags usage, VkImageAspectFlags aspect);

// A barrier moving the whole of `image` (one level, one layer) between layouts.
VkImageMemoryBarrier imageBarrier(VkImage image, VkImageAspectFlags aspect,
                                  VkImageLayout old_layout, VkImageLayout new_layout,
                                  VkAccessFlags src_access, VkAccessFlags dst_access);

}  // namespace tb::gpu
