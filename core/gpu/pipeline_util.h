// Small builders shared by the pipelines: shader modules, layouts, and descriptor sets
// made only of storage buffers (all the harness shaders need).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string_view>

#include "core/gpu/vk_handle.h"

namespace tb::gpu {

// SPIR-V of an embedded shader (shaders/<path>); throws GpuError naming it when absent.
std::span<const uint32_t> requireEmbeddedShader(std::string_view path);

VkShaderModuleOwner createShaderModule(VkDevice device, std::span<const uint32_t> spirv);

VkPipelineLayoutOwner createPipelineLayout(VkDevice device, VkDescriptorSetLayout set_layout,
                                           VkShaderStageFlags push_stages,
                                           uint32_t push_constant_bytes);
// Set i uses set_layouts[i].
VkPipelineLayoutOwner createPipelineLayout(VkDevice device,
                                           std::span<const VkDescriptorSetLayout> set_layouts,
                                           VkShaderStageFlags push_stages,
                                           uint32_t push_constant_bytes);

// Binding i is a storage buffer visible to stages[i].
VkDescriptorSetLayoutOwner createStorageBufferSetLayout(VkDevice device,
                                                        std::span<const VkShaderStageFlags> stages);

// One descriptor set of `binding_count` storage buffers, with the pool that owns it.
struct StorageBufferSet {
  StorageBufferSet() = default;
  StorageBufferSet(VkDevice device, VkDescriptorSetLayout layout, uint32_t binding_count);
  // Points binding i at buffers[i] (whole range). Only while no submission uses the set.
  void bind(VkDevice device, std::span<const VkBuffer> buffers) const;
  // Points binding i at the first ranges[i] bytes of buffers[i] (the shader's .length()
  // sees that range). Only while no submission uses the set.
  void bind(VkDevice device, std::span<const VkBuffer> buffers,
            std::span<const VkDeviceSize> ranges) const;

  VkDescriptorPoolOwner pool;
  VkDescriptorSet set = VK_NULL_HANDLE;
};

VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits stage, VkShaderModule module);

// State shared by the harness's graphics pipelines: dynamic rendering, no vertex buffers
// (the shaders pull their data), filled polygons, no face culling. Callers set the rest
// on `info`, then create. Not copyable: `info` points into the object.
struct GraphicsPipelineBase {
  GraphicsPipelineBase(std::span<const VkPipelineShaderStageCreateInfo> stages,
                       VkPrimitiveTopology topology, VkPipelineLayout layout,
                       const VkPipelineRenderingCreateInfo* rendering);
  GraphicsPipelineBase(const GraphicsPipelineBase&) = delete;
  GraphicsPipelineBase& operator=(const GraphicsPipelineBase&) = delete;

  VkPipelineOwner create(VkDevice device, const char* what) const;

  VkPipelineVertexInputStateCreateInfo vertex_input;
  VkPipelineInputAssemblyStateCreateInfo assembly;
  VkPipelineRasterizationStateCreateInfo raster;
  VkGraphicsPipelineCreateInfo info;
};

}  // namespace tb::gpu
