// Graphics pipelines VS -> TCS -> TES with rasterizer discard, one per
// (domain, spacing, winding, point mode, output), cached per device and warmed up:
// lavapipe compiles shaders at the first draw, not at pipeline creation.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>

#include "harness/gpu/buffer.h"
#include "harness/gpu/spirv_patch.h"
#include "harness/gpu/vk_handle.h"
#include "harness/tess/tessellator.h"

namespace tb::gpu {

class Context;

enum class TessOutput {
  kCapture,  // TES writes gl_TessCoord bits to transform-feedback buffer 0 (12 bytes/vertex)
  kPlain,    // TES writes only gl_Position: the throughput probe
};

// VK_EXT_transform_feedback entry points (not exported by the loader).
struct XfbCommands {
  PFN_vkCmdBindTransformFeedbackBuffersEXT bind = nullptr;
  PFN_vkCmdBeginTransformFeedbackEXT begin = nullptr;
  PFN_vkCmdEndTransformFeedbackEXT end = nullptr;
};

class TessPipelines {
 public:
  explicit TessPipelines(Context& context);

  VkPipeline get(const TessModes& modes, TessOutput output);
  VkPipelineLayout layout() const { return layout_.get(); }
  const XfbCommands& xfb() const { return xfb_; }

  // gl_TessLevelOuter/Inner as raw float bits, for the bound pipeline's TCS.
  void pushLevels(VkCommandBuffer cmd, const tess::Levels& levels) const;

 private:
  Context& context_;
  XfbCommands xfb_;
  VkPipelineLayoutOwner layout_;
  VkShaderModuleOwner vertex_;
  VkShaderModuleOwner control_;
  Buffer warm_up_capture_;
  std::map<uint32_t, VkPipelineOwner> pipelines_;
};

// Starts a 1x1 render area with no attachments: enough for draws under rasterizer discard.
void beginDiscardRendering(VkCommandBuffer cmd);

}  // namespace tb::gpu
