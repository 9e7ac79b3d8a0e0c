#include "core/gpu/sampled_image.h"

#include <string>

#include "core/gpu/context.h"
#include "core/gpu/device_image.h"
#include "core/gpu/gpu_error.h"

namespace tb::gpu {

VkFormat floatImageFormat(uint32_t channels, uint32_t bytes_per_channel) {
  if (channels == 1 && bytes_per_channel == 2) return VK_FORMAT_R16_SFLOAT;
  if (channels == 1 && bytes_per_channel == 4) return VK_FORMAT_R32_SFLOAT;
  if (channels == 4 && bytes_per_channel == 2) return VK_FORMAT_R16G16B16A16_SFLOAT;
  if (channels == 4 && bytes_per_channel == 4) return VK_FORMAT_R32G32B32A32_SFLOAT;
  throw GpuError("no float image format of " + std::to_string(channels) + " channels of " +
                 std::to_string(bytes_per_channel) + " bytes");
}

namespace {

uint32_t texelBytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R16_SFLOAT:
      return 2;
    case VK_FORMAT_R32_SFLOAT:
      return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return 16;
    default:
      throw GpuError("sampled image: unsupported format " + std::to_string(format));
  }
}

}  // namespace

SampledImage::SampledImage(Context& context, VkFormat format, uint32_t width, uint32_t height,
                           std::span<const std::byte> texels) {
  if (uint64_t(width) * height * texelBytes(format) != texels.size() || width == 0 || height == 0) {
    throw GpuError("sampled image: " + std::to_string(texels.size()) + " bytes for " +
                   std::to_string(width) + "x" + std::to_string(height) + " texels");
  }
  VkFormatProperties properties;
  vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
  constexpr VkFormatFeatureFlags kNeeded =
      VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  if ((properties.optimalTilingFeatures & kNeeded) != kNeeded) {
    throw GpuError("the device cannot sample image format " + std::to_string(format));
  }
  image_ = createDeviceImage(context, width, height, format,
                             VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT);
  const VkDevice device = context.device();
  const VkImage image = image_.image.get();
  Buffer staging(context, texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  staging.write(texels.data(), texels.size());
  context.submitAndWait([&](VkCommandBuffer cmd) {
    VkImageMemoryBarrier to_transfer =
        imageBarrier(image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                         0, nullptr, 0, nullptr, 1, &to_transfer);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(cmd, staging.handle(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &copy);
    VkImageMemoryBarrier to_read =
        imageBarrier(image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_ACCESS_SHADER_READ_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TESSELLATION_EVALUATION_SHADER_BIT, 0, 0, nullptr, 0,
                         nullptr, 1, &to_read);
  });

  auto sampler_info = vkStruct<VkSamplerCreateInfo>(VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO);
  sampler_info.magFilter = VK_FILTER_NEAREST;
  sampler_info.minFilter = VK_FILTER_NEAREST;
  sampler_info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  sampler_info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler_info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  sampler_info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSampler sampler = VK_NULL_HANDLE;
  vkCheck(vkCreateSampler(device, &sampler_info, nullptr, &sampler), "vkCreateSampler");
  sampler_ = VkSamplerOwner(device, sampler);
}

VkDescriptorSetLayoutOwner createDisplacementSetLayout(VkDevice device) {
  VkDescriptorSetLayoutBinding bindings[2] = {};
  bindings[0].binding = 0;
  bindings[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  bindings[0].descriptorCount = 1;
  bindings[0].stageFlags = VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
  bindings[1].binding = 1;
  bindings[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  bindings[1].descriptorCount = 1;
  bindings[1].stageFlags = VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
  auto info = vkStruct<VkDescriptorSetLayoutCreateInfo>(
      VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  info.bindingCount = 2;
  info.pBindings = bindings;
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  vkCheck(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout),
          "vkCreateDescriptorSetLayout (displacement)");
  return VkDescriptorSetLayoutOwner(device, layout);
}

DisplacementSet::DisplacementSet(VkDevice device, VkDescriptorSetLayout layout,
                                 const SampledImage& image, const Buffer& patch_words) {
  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1},
                                         {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
  auto pool_info =
      vkStruct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 2;
  pool_info.pPoolSizes = sizes;
  VkDescriptorPool raw_pool = VK_NULL_HANDLE;
  vkCheck(vkCreateDescriptorPool(device, &pool_info, nullptr, &raw_pool),
          "vkCreateDescriptorPool (displacement)");
  pool = VkDescriptorPoolOwner(device, raw_pool);
  auto alloc =
      vkStruct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  alloc.descriptorPool = raw_pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  vkCheck(vkAllocateDescriptorSets(device, &alloc, &set),
          "vkAllocateDescriptorSets (displacement)");
  const VkDescriptorImageInfo image_info{image.sampler(), image.view(),
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkDescriptorBufferInfo buffer_info{patch_words.handle(), 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet writes[2];
  writes[0] = vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  writes[0].dstSet = set;
  writes[0].dstBinding = 0;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  writes[0].pImageInfo = &image_info;
  writes[1] = vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
  writes[1].dstSet = set;
  writes[1].dstBinding = 1;
  writes[1].descriptorCount = 1;
  writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  writes[1].pBufferInfo = &buffer_info;
  vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);
}

}  // namespace tb::gpu
