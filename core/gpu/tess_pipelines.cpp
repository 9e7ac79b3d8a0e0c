#include "core/gpu/tess_pipelines.h"

#include <bit>

#include "core/gpu/context.h"
#include "core/gpu/pipeline_util.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

// uvec4 outer bits + uvec2 inner bits (shaders/gpu/tess_levels.tesc).
constexpr uint32_t kLevelPushBytes = 24;
constexpr VkDeviceSize kWarmUpCaptureBytes = 4096;

// kPow2 and kInteger share SpacingEqual, hence one pipeline.
uint32_t pipelineKey(const TessModes& modes, TessOutput output) {
  const tess::Spacing spacing =
      modes.spacing == tess::Spacing::kPow2 ? tess::Spacing::kInteger : modes.spacing;
  return static_cast<uint32_t>(modes.domain) | static_cast<uint32_t>(spacing) << 4 |
         uint32_t{modes.ccw} << 8 | uint32_t{modes.point_mode} << 9 |
         static_cast<uint32_t>(output) << 10;
}

template <class Fn>
Fn deviceFunction(VkDevice device, const char* name) {
  auto fn = reinterpret_cast<Fn>(vkGetDeviceProcAddr(device, name));
  if (!fn) throw GpuError(std::string("missing Vulkan entry point ") + name);
  return fn;
}

VkPipelineOwner createPipeline(VkDevice device, VkPipelineLayout layout, VkShaderModule vertex,
                               VkShaderModule control, VkShaderModule evaluation) {
  const VkPipelineShaderStageCreateInfo stages[] = {
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, control),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, evaluation),
  };
  return createDiscardTessPipeline(device, layout, stages, 1,
                                   "vkCreateGraphicsPipelines (tessellation)");
}

}  // namespace

TessPipelines::TessPipelines(Context& context) : context_(context) {
  context.requireFeatures(tessCaptureFeatures(), "GPU tessellation");
  const VkDevice device = context.device();
  xfb_.bind = deviceFunction<PFN_vkCmdBindTransformFeedbackBuffersEXT>(
      device, "vkCmdBindTransformFeedbackBuffersEXT");
  xfb_.begin =
      deviceFunction<PFN_vkCmdBeginTransformFeedbackEXT>(device, "vkCmdBeginTransformFeedbackEXT");
  xfb_.end =
      deviceFunction<PFN_vkCmdEndTransformFeedbackEXT>(device, "vkCmdEndTransformFeedbackEXT");
  layout_ = createPipelineLayout(device, VK_NULL_HANDLE, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
                                 kLevelPushBytes);
  vertex_ = createShaderModule(device, requireEmbeddedShader("gpu/tess_patch.vert"));
  control_ = createShaderModule(device, requireEmbeddedShader("gpu/tess_levels.tesc"));
  warm_up_capture_ =
      Buffer(context, kWarmUpCaptureBytes, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT);
}

VkPipeline TessPipelines::get(const TessModes& modes, TessOutput output) {
  const uint32_t key = pipelineKey(modes, output);
  if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second.get();

  const char* tes_path =
      output == TessOutput::kCapture ? "gpu/tess_capture.tese" : "gpu/tess_plain.tese";
  const std::vector<uint32_t> tes_spirv = withTessModes(requireEmbeddedShader(tes_path), modes);
  const VkShaderModuleOwner evaluation = createShaderModule(context_.device(), tes_spirv);
  VkPipelineOwner owner = createPipeline(context_.device(), layout_.get(), vertex_.get(),
                                         control_.get(), evaluation.get());
  const VkPipeline pipeline = owner.get();
  pipelines_.emplace(key, std::move(owner));

  // Warm-up: one level-1 patch, captured when the pipeline captures, so the JIT runs now
  // and not inside the first timed submission.
  context_.submitAndWait([&](VkCommandBuffer cmd) {
    beginDiscardRendering(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    pushLevels(cmd, tess::Levels{});
    const bool capture = output == TessOutput::kCapture;
    if (capture) {
      const VkBuffer buffer = warm_up_capture_.handle();
      const VkDeviceSize offset = 0;
      const VkDeviceSize size = kWarmUpCaptureBytes;
      xfb_.bind(cmd, 0, 1, &buffer, &offset, &size);
      xfb_.begin(cmd, 0, 0, nullptr, nullptr);
    }
    vkCmdDraw(cmd, 1, 1, 0, 0);
    if (capture) xfb_.end(cmd, 0, 0, nullptr, nullptr);
    vkCmdEndRendering(cmd);
  });
  return pipeline;
}

void TessPipelines::pushLevels(VkCommandBuffer cmd, const tess::Levels& levels) const {
  uint32_t bits[6];
  for (int i = 0; i < 4; ++i) bits[i] = std::bit_cast<uint32_t>(levels.outer[i]);
  for (int i = 0; i < 2; ++i) bits[4 + i] = std::bit_cast<uint32_t>(levels.inner[i]);
  vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, 0,
                     kLevelPushBytes, bits);
}

VkPipelineOwner createDiscardTessPipeline(VkDevice device, VkPipelineLayout layout,
                                          std::span<const VkPipelineShaderStageCreateInfo> stages,
                                          uint32_t patch_control_points, const char* what,
                                          VkPipelineCreateFlags flags) {
  auto tessellation = vkStruct<VkPipelineTessellationStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO);
  tessellation.patchControlPoints = patch_control_points;
  // Lower-left origin makes layout(ccw) counter-clockwise in (u, v) with v up, the
  // convention of tess::Options::ccw (core/tess/stitch.h, GL's). Vulkan's default
  // upper-left origin would reverse every triangle; gl_TessCoord is the same either way.
  auto origin = vkStruct<VkPipelineTessellationDomainOriginStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_DOMAIN_ORIGIN_STATE_CREATE_INFO);
  origin.domainOrigin = VK_TESSELLATION_DOMAIN_ORIGIN_LOWER_LEFT;
  tessellation.pNext = &origin;
  // Zero attachments: under rasterizer discard nothing is written.
  const auto rendering =
      vkStruct<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  GraphicsPipelineBase base(stages, VK_PRIMITIVE_TOPOLOGY_PATCH_LIST, layout, &rendering);
  base.raster.rasterizerDiscardEnable = VK_TRUE;
  base.info.pTessellationState = &tessellation;
  base.info.flags = flags;
  return base.create(device, what);
}

void beginDiscardRendering(VkCommandBuffer cmd) {
  auto info = vkStruct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
  info.renderArea = {{0, 0}, {1, 1}};
  info.layerCount = 1;
  vkCmdBeginRendering(cmd, &info);
}

}  // namespace tb::gpu
