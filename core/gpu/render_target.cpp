#include "core/gpu/render_target.h"

#include "core/gpu/context.h"
#include "core/gpu/device_image.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
constexpr VkBufferUsageFlags kReadback = VK_BUFFER_USAGE_TRANSFER_DST_BIT;

AttachmentImage createAttachment(Context& context, uint32_t width, uint32_t height, VkFormat format,
                                 VkImageUsageFlags usage, VkImageAspectFlags aspect) {
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
  const VkFormatFeatureFlags needed = (aspect & VK_IMAGE_ASPECT_DEPTH_BIT)
                                          ? VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT
                                          : VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
  if ((properties.optimalTilingFeatures & needed) != needed) {
    throw GpuError("render target format " + std::to_string(format) + " is not renderable");
  }
  return createDeviceImage(context, width, height, format, usage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           aspect);
}

VkRenderingAttachmentInfo clearedAttachment(VkImageView view, VkImageLayout layout,
                                            VkClearValue clear) {
  auto info = vkStruct<VkRenderingAttachmentInfo>(VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
  info.imageView = view;
  info.imageLayout = layout;
  info.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  info.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  info.clearValue = clear;
  return info;
}

}  // namespace

RenderTarget::RenderTarget(Context& context, uint32_t width_px, uint32_t height_px)
    : context_(context), width_(width_px), height_(height_px) {
  constexpr VkImageUsageFlags kColorUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  color_ = createAttachment(context, width_, height_, kColorFormat, kColorUsage,
                            VK_IMAGE_ASPECT_COLOR_BIT);
  id_ =
      createAttachment(context, width_, height_, kIdFormat, kColorUsage, VK_IMAGE_ASPECT_COLOR_BIT);
  depth_ = createAttachment(context, width_, height_, kDepthFormat,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
  const VkDeviceSize pixels = VkDeviceSize{width_} * height_;
  color_readback_ = Buffer(context, pixels * 4, kReadback);
  id_readback_ = Buffer(context, pixels * 4, kReadback);
  depth_readback_ = Buffer(context, pixels * 4, kReadback);
  const VkDevice device = context.device();
  const VkShaderStageFlags stages[] = {VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_FRAGMENT_BIT};
  set_layout_ = createStorageBufferSetLayout(device, stages);
  layout_ = createPipelineLayout(device, set_layout_.get(), 0, 0);
  descriptors_ = StorageBufferSet(device, set_layout_.get(), 2);
  pipeline_ = createPipeline(VK_CULL_MODE_NONE);
}

VkPipelineOwner RenderTarget::createPipeline(VkCullModeFlags cull_mode) {
  const VkDevice device = context_.device();
  const VkShaderModuleOwner vertex =
      createShaderModule(device, requireEmbeddedShader("gpu/id_triangles.vert"));
  const VkShaderModuleOwner fragment =
      createShaderModule(device, requireEmbeddedShader("gpu/id_triangles.frag"));
  const VkPipelineShaderStageCreateInfo shader_stages[] = {
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, vertex.get()),
      shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, fragment.get()),
  };

  const VkViewport viewport{0, 0, float(width_), float(height_), 0, 1};
  const VkRect2D scissor{{0, 0}, {width_, height_}};
  auto viewport_state = vkStruct<VkPipelineViewportStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewport_state.viewportCount = 1;
  viewport_state.pViewports = &viewport;
  viewport_state.scissorCount = 1;
  viewport_state.pScissors = &scissor;
  auto multisample = vkStruct<VkPipelineMultisampleStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  auto depth = vkStruct<VkPipelineDepthStencilStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO);
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;
  VkPipelineColorBlendAttachmentState blend[2] = {};
  for (VkPipelineColorBlendAttachmentState& b : blend) {
    b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                       VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  }
  auto blend_state = vkStruct<VkPipelineColorBlendStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO);
  blend_state.attachmentCount = 2;
  blend_state.pAttachments = blend;
  const VkFormat color_formats[] = {kColorFormat, kIdFormat};
  auto rendering =
      vkStruct<VkPipelineRenderingCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO);
  rendering.colorAttachmentCount = 2;
  rendering.pColorAttachmentFormats = color_formats;
  rendering.depthAttachmentFormat = kDepthFormat;

  GraphicsPipelineBase base(shader_stages, VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST, layout_.get(),
                            &rendering);
  base.info.pViewportState = &viewport_state;
  base.info.pMultisampleState = &multisample;
  base.info.pDepthStencilState = &depth;
  base.info.pColorBlendState = &blend_state;
  // Front: counter-clockwise in framebuffer coordinates, by the specification's signed
  // area (which counts y down), i.e. det[x y w] < 0 of the clip vertices (render_target.h).
  base.raster.cullMode = cull_mode;
  base.raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  return base.create(device, "vkCreateGraphicsPipelines (ID render target)");
}

double RenderTarget::drawTriangles(std::span<const std::array<float, 4>> clip_positions,
                                   std::span<const uint32_t> triangle_ids) {
  return drawTriangles(clip_positions, triangle_ids, DrawOptions{});
}

double RenderTarget::drawTriangles(std::span<const std::array<float, 4>> clip_positions,
                                   std::span<const uint32_t> triangle_ids,
                                   const DrawOptions& options) {
  const uint32_t triangle_count = static_cast<uint32_t>(triangle_ids.size());
  if (clip_positions.size() != size_t{triangle_count} * 3) {
    throw GpuError("RenderTarget::drawTriangles: need 3 positions per triangle ID");
  }
  ensureCapacity(context_, positions_, clip_positions.size_bytes() + 16, kStorage);
  ensureCapacity(context_, triangle_ids_, triangle_ids.size_bytes() + 4, kStorage);
  positions_.write(clip_positions.data(), clip_positions.size_bytes());
  triangle_ids_.write(triangle_ids.data(), triangle_ids.size_bytes());
  const VkBuffer storage[] = {positions_.handle(), triangle_ids_.handle()};
  descriptors_.bind(context_.device(), storage);
  if (options.cull_back_faces && !cull_back_pipeline_) {
    cull_back_pipeline_ = createPipeline(VK_CULL_MODE_BACK_BIT);
  }
  const VkPipeline pipeline = options.cull_back_faces ? cull_back_pipeline_.get() : pipeline_.get();
  const bool read_all = options.readback == Readback::kAll;
  colors_and_depths_read_ = read_all;

  constexpr VkImageLayout kColorLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  constexpr VkImageLayout kDepthLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  constexpr VkImageLayout kCopyLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  constexpr VkAccessFlags kColorWrite = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  constexpr VkAccessFlags kDepthWrite = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  constexpr VkImageAspectFlags kColorAspect = VK_IMAGE_ASPECT_COLOR_BIT;
  constexpr VkImageAspectFlags kDepthAspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  const VkImage color = color_.image.get();
  const VkImage id = id_.image.get();
  const VkImage depth = depth_.image.get();

  return context_.submitAndWait([&](VkCommandBuffer cmd) {
    const VkImageMemoryBarrier to_attachment[] = {
        imageBarrier(color, kColorAspect, VK_IMAGE_LAYOUT_UNDEFINED, kColorLayout, 0, kColorWrite),
        imageBarrier(id, kColorAspect, VK_IMAGE_LAYOUT_UNDEFINED, kColorLayout, 0, kColorWrite),
        imageBarrier(depth, kDepthAspect, VK_IMAGE_LAYOUT_UNDEFINED, kDepthLayout, 0, kDepthWrite),
    };
    vkCmdPipelineBarrier(
        cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT,
        0, 0, nullptr, 0, nullptr, 3, to_attachment);

    VkClearValue clear_color{}, clear_id{}, clear_depth{};
    clear_id.color.uint32[0] = kNoId;
    clear_depth.depthStencil = {1.0f, 0};
    VkRenderingAttachmentInfo colors[] = {
        clearedAttachment(color_.view.get(), kColorLayout, clear_color),
        clearedAttachment(id_.view.get(), kColorLayout, clear_id),
    };
    VkRenderingAttachmentInfo depth_attachment =
        clearedAttachment(depth_.view.get(), kDepthLayout, clear_depth);
    if (!read_all) {  // nobody reads colour: neither clear nor keep it; depth is not kept
      colors[0].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
      colors[0].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
      depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    }
    auto rendering = vkStruct<VkRenderingInfo>(VK_STRUCTURE_TYPE_RENDERING_INFO);
    rendering.renderArea = {{0, 0}, {width_, height_}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 2;
    rendering.pColorAttachments = colors;
    rendering.pDepthAttachment = &depth_attachment;
    vkCmdBeginRendering(cmd, &rendering);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1,
                            &descriptors_.set, 0, nullptr);
    if (triangle_count > 0) vkCmdDraw(cmd, triangle_count * 3, 1, 0, 0);
    vkCmdEndRendering(cmd);

    constexpr VkAccessFlags kCopyRead = VK_ACCESS_TRANSFER_READ_BIT;
    const VkImageMemoryBarrier to_copy[] = {
        imageBarrier(color, kColorAspect, kColorLayout, kCopyLayout, kColorWrite, kCopyRead),
        imageBarrier(id, kColorAspect, kColorLayout, kCopyLayout, kColorWrite, kCopyRead),
        imageBarrier(depth, kDepthAspect, kDepthLayout, kCopyLayout, kDepthWrite, kCopyRead),
    };
    vkCmdPipelineBarrier(
        cmd,
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
        VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, nullptr, 0, nullptr, 3, to_copy);
    VkBufferImageCopy region{};
    region.imageExtent = {width_, height_, 1};
    region.imageSubresource = {kColorAspect, 0, 0, 1};
    vkCmdCopyImageToBuffer(cmd, id, kCopyLayout, id_readback_.handle(), 1, &region);
    if (read_all) {
      vkCmdCopyImageToBuffer(cmd, color, kCopyLayout, color_readback_.handle(), 1, &region);
      region.imageSubresource.aspectMask = kDepthAspect;
      vkCmdCopyImageToBuffer(cmd, depth, kCopyLayout, depth_readback_.handle(), 1, &region);
    }

    auto to_host = vkStruct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &to_host, 0, nullptr, 0, nullptr);
  });
}

std::vector<uint32_t> RenderTarget::ids() const {
  const auto words = id_readback_.as<uint32_t>();
  return {words.begin(), words.end()};
}

std::span<const uint32_t> RenderTarget::mappedIds() const {
  const auto words = id_readback_.as<const uint32_t>();
  return words.first(size_t{width_} * height_);
}

std::vector<uint32_t> RenderTarget::colors() const {
  if (!colors_and_depths_read_) {
    throw GpuError("RenderTarget::colors: the last draw did not read colours back");
  }
  const auto words = color_readback_.as<uint32_t>();
  return {words.begin(), words.end()};
}

std::vector<float> RenderTarget::depths() const {
  if (!colors_and_depths_read_) {
    throw GpuError("RenderTarget::depths: the last draw did not read depths back");
  }
  const auto values = depth_readback_.as<float>();
  return {values.begin(), values.end()};
}

}  // namespace tb::gpu
