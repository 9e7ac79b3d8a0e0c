// An offscreen colour + depth + 32-bit ID target with readback. The ID buffer says which
// triangle (patch, for the culling measure) covers each pixel, so a culled patch that
// covers pixels in an unculled render is a false cull.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/gpu/buffer.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

class Context;

struct AttachmentImage {
  VkMemoryOwner memory;  // first, so it is freed after the image and view
  VkImageOwner image;
  VkImageViewOwner view;
};

class RenderTarget {
 public:
  static constexpr uint32_t kNoId = 0xffffffffu;  // ID of a pixel no triangle covers
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
  static constexpr VkFormat kIdFormat = VK_FORMAT_R32_UINT;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  RenderTarget(Context& context, uint32_t width_px, uint32_t height_px);

  // Clears (colour 0, depth 1, ID kNoId), then draws one triangle per 3 clip-space
  // positions (x, y, z, w; Vulkan convention, y down), triangle t writing
  // triangle_ids[t], depth test LESS, no culling; then reads everything back.
  // Returns host seconds, submit to fence.
  double drawTriangles(std::span<const std::array<float, 4>> clip_positions,
                       std::span<const uint32_t> triangle_ids);

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  // Row-major, top row first, width * height entries, as of the last drawTriangles.
  std::vector<uint32_t> ids() const;
  std::vector<uint32_t> colors() const;  // RGBA8, R in the low byte
  std::vector<float> depths() const;     // [0, 1]

 private:
  void createPipeline();

  Context& context_;
  uint32_t width_;
  uint32_t height_;
  AttachmentImage color_;
  AttachmentImage id_;
  AttachmentImage depth_;
  Buffer color_readback_;
  Buffer id_readback_;
  Buffer depth_readback_;
  Buffer positions_;
  Buffer triangle_ids_;
  VkDescriptorSetLayoutOwner set_layout_;
  VkPipelineLayoutOwner layout_;
  VkPipelineOwner pipeline_;
  StorageBufferSet descriptors_;
};

}  // namespace tb::gpu
