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
#include "core/gpu/device_image.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

class Context;

using AttachmentImage = DeviceImage;

class RenderTarget {
 public:
  static constexpr uint32_t kNoId = 0xffffffffu;  // ID of a pixel no triangle covers
  static constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
  static constexpr VkFormat kIdFormat = VK_FORMAT_R32_UINT;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  // What a draw reads back after rendering. kIdsOnly skips the colour and depth copies
  // (8 of the 12 bytes a pixel; at 1920 x 1080, 16 MB less to copy) and lets the device
  // discard colour and depth once the render ends. On lavapipe the render itself dominates
  // (no measurable time saved); on a GPU it spares the readback bandwidth.
  enum class Readback { kAll, kIdsOnly };

  struct DrawOptions {
    // Fixed-function back-face culling (VK_CULL_MODE_BACK_BIT). Front faces are
    // VK_FRONT_FACE_COUNTER_CLOCKWISE: counter-clockwise on the image as read back (top
    // row first), which is det[x y w] < 0 over the three clip vertices (rows (x, y, w)).
    // With a projection that flips y into Vulkan's clip space (core/view/camera.h's
    // perspective, so the image is upright), that is a world triangle (v0, v1, v2) whose
    // normal (v1 - v0) x (v2 - v0) points towards the eye: counter-clockwise seen from
    // the eye. Every technique's tessellated triangles face out of a closed surface this
    // way (tests/measures/cull_oracle_test.cpp checks each).
    bool cull_back_faces = false;
    Readback readback = Readback::kAll;
  };

  RenderTarget(Context& context, uint32_t width_px, uint32_t height_px);

  // Clears (colour 0, depth 1, ID kNoId), then draws one triangle per 3 clip-space
  // positions (x, y, z, w; Vulkan convention, y down), triangle t writing
  // triangle_ids[t], depth test LESS, no culling unless options say so; then reads back
  // what options.readback names. Returns host seconds, submit to fence.
  double drawTriangles(std::span<const std::array<float, 4>> clip_positions,
                       std::span<const uint32_t> triangle_ids);
  double drawTriangles(std::span<const std::array<float, 4>> clip_positions,
                       std::span<const uint32_t> triangle_ids, const DrawOptions& options);

  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  // Row-major, top row first, width * height entries, as of the last drawTriangles.
  std::vector<uint32_t> ids() const;
  // The same IDs in place, without a copy: valid until the next drawTriangles.
  std::span<const uint32_t> mappedIds() const;
  // These two throw GpuError when the last draw did not read them back (kIdsOnly), or
  // before the first draw.
  std::vector<uint32_t> colors() const;  // RGBA8, R in the low byte
  std::vector<float> depths() const;     // [0, 1]

 private:
  VkPipelineOwner createPipeline(VkCullModeFlags cull_mode);

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
  VkPipelineOwner pipeline_;            // no culling
  VkPipelineOwner cull_back_pipeline_;  // made on first use (a pipeline costs lavapipe ~ms)
  StorageBufferSet descriptors_;
  bool colors_and_depths_read_ = false;  // by the last draw
};

}  // namespace tb::gpu
