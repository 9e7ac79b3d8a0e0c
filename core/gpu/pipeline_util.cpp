#include "core/gpu/pipeline_util.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/gpu/gpu_error.h"
#include "core/gpu/vk_handle.h"
#include "shaders/embedded_shaders.h"

namespace tb::gpu {

std::span<const uint32_t> requireEmbeddedShader(std::string_view path) {
  const std::span<const uint32_t> spirv = embeddedShader(path);
  if (spirv.empty()) {
    throw GpuError(
        "shader '" + std::string(path) +
        "' is neither built in (shaders/) nor registered by a plug-in (PluginHost::addShader)");
  }
  return spirv;
}

VkShaderModuleOwner createShaderModule(VkDevice device, std::span<const uint32_t> spirv) {
  auto info = vkStruct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  vkCheck(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return VkShaderModuleOwner(device, module);
}

VkPipelineLayoutOwner createPipelineLayout(VkDevice device, VkDescriptorSetLayout set_layout,
                                           VkShaderStageFlags push_stages,
                                           uint32_t push_constant_bytes) {
  return createPipelineLayout(
      device, std::span<const VkDescriptorSetLayout>(&set_layout, set_layout != VK_NULL_HANDLE),
      push_stages, push_constant_bytes);
}

VkPipelineLayoutOwner createPipelineLayout(VkDevice device,
                                           std::span<const VkDescriptorSetLayout> set_layouts,
                                           VkShaderStageFlags push_stages,
                                           uint32_t push_constant_bytes) {
  VkPushConstantRange range{push_stages, 0, push_constant_bytes};
  auto info = vkStruct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
  info.setLayoutCount = uint32_t(set_layouts.size());
  info.pSetLayouts = set_layouts.data();
  info.pushConstantRangeCount = push_constant_bytes > 0 ? 1 : 0;
  info.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  vkCheck(vkCreatePipelineLayout(device, &info, nullptr, &layout), "vkCreatePipelineLayout");
  return VkPipelineLayoutOwner(device, layout);
}

VkDescriptorSetLayoutOwner createStorageBufferSetLayout(
    VkDevice device, std::span<const VkShaderStageFlags> stages) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (uint32_t i = 0; i < stages.size(); ++i) {
    bindings.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages[i], nullptr});
  }
  auto info = vkStruct<VkDescriptorSetLayoutCreateInfo>(
      VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
  info.bindingCount = static_cast<uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  vkCheck(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout),
          "vkCreateDescriptorSetLayout");
  return VkDescriptorSetLayoutOwner(device, layout);
}

StorageBufferSet::StorageBufferSet(VkDevice device, VkDescriptorSetLayout layout,
                                   uint32_t binding_count) {
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, std::max(binding_count, 1u)};
  auto pool_info =
      vkStruct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
  VkDescriptorPool raw_pool = VK_NULL_HANDLE;
  vkCheck(vkCreateDescriptorPool(device, &pool_info, nullptr, &raw_pool), "vkCreateDescriptorPool");
  pool = VkDescriptorPoolOwner(device, raw_pool);
  auto alloc =
      vkStruct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
  alloc.descriptorPool = raw_pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  vkCheck(vkAllocateDescriptorSets(device, &alloc, &set), "vkAllocateDescriptorSets");
}

void StorageBufferSet::bind(VkDevice device, std::span<const VkBuffer> buffers) const {
  const std::vector<VkDeviceSize> whole(buffers.size(), VK_WHOLE_SIZE);
  bind(device, buffers, whole);
}

void StorageBufferSet::bind(VkDevice device, std::span<const VkBuffer> buffers,
                            std::span<const VkDeviceSize> ranges) const {
  std::vector<VkDescriptorBufferInfo> infos;
  for (size_t i = 0; i < buffers.size(); ++i) infos.push_back({buffers[i], 0, ranges[i]});
  std::vector<VkWriteDescriptorSet> writes;
  for (uint32_t i = 0; i < infos.size(); ++i) {
    auto write = vkStruct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
    write.dstSet = set;
    write.dstBinding = i;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &infos[i];
    writes.push_back(write);
  }
  vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);
}

VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits stage, VkShaderModule module) {
  auto info = vkStruct<VkPipelineShaderStageCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO);
  info.stage = stage;
  info.module = module;
  info.pName = "main";
  return info;
}

GraphicsPipelineBase::GraphicsPipelineBase(std::span<const VkPipelineShaderStageCreateInfo> stages,
                                           VkPrimitiveTopology topology, VkPipelineLayout layout,
                                           const VkPipelineRenderingCreateInfo* rendering)
    : vertex_input(vkStruct<VkPipelineVertexInputStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO)),
      assembly(vkStruct<VkPipelineInputAssemblyStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO)),
      raster(vkStruct<VkPipelineRasterizationStateCreateInfo>(
          VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO)),
      info(
          vkStruct<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO)) {
  assembly.topology = topology;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  info.pNext = rendering;
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pRasterizationState = &raster;
  info.layout = layout;
}

VkPipelineOwner GraphicsPipelineBase::create(VkDevice device, const char* what) const {
  VkPipeline pipeline = VK_NULL_HANDLE;
  vkCheck(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline), what);
  return VkPipelineOwner(device, pipeline);
}

}  // namespace tb::gpu
