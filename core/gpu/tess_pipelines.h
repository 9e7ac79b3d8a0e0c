// Graphics pipelines VS -> TCS -> TES with rasterizer discard, one per
// (domain, spacing, winding, point mode, output), cached per device and warmed up:
// lavapipe compiles shaders at the first draw, not at pipeline creation.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <span>

#include "core/gpu/buffer.h"
#include "core/gpu/spirv_patch.h"
#include "core/gpu/vk_handle.h"
#include "core/tess/tessellator.h"

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

// A VS -> TCS -> TES pipeline under rasterizer discard with zero attachments and the
// lower-left domain origin (layout(ccw) is counter-clockwise in (u, v) with v up).
// `stages` are the three shader stages; the tess capture and patch programs share it.
// `flags`: VkGraphicsPipelineCreateInfo::flags (the capture bits of pipeline_executables.h).
VkPipelineOwner createDiscardTessPipeline(VkDevice device, VkPipelineLayout layout,
                                          std::span<const VkPipelineShaderStageCreateInfo> stages,
                                          uint32_t patch_control_points, const char* what,
                                          VkPipelineCreateFlags flags = 0);

// Statistics every tessellation query collects, reported in this bit order: VS
// invocations, clipping invocations, clipping primitives, TCS patches, TES invocations
// (Vulkan spec, "Pipeline Statistics Queries").
inline constexpr VkQueryPipelineStatisticFlags kTessStatisticFlags =
    VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT |
    VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT |
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_CONTROL_SHADER_PATCHES_BIT |
    VK_QUERY_PIPELINE_STATISTIC_TESSELLATION_EVALUATION_SHADER_INVOCATIONS_BIT;
inline constexpr uint32_t kTessStatisticCount = 5;

}  // namespace tb::gpu
