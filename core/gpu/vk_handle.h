// Move-only owners of Vulkan device-level handles, so a throw mid-setup leaks nothing.
#pragma once

#include <vulkan/vulkan.h>

#include <utility>

namespace tb::gpu {

template <class Handle, auto kDestroy>
class DeviceHandle {
 public:
  DeviceHandle() = default;
  DeviceHandle(VkDevice device, Handle handle) : device_(device), handle_(handle) {}
  ~DeviceHandle() { reset(); }
  DeviceHandle(DeviceHandle&& other) noexcept
      : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
  DeviceHandle& operator=(DeviceHandle&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }
  DeviceHandle(const DeviceHandle&) = delete;
  DeviceHandle& operator=(const DeviceHandle&) = delete;

  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }
  void reset() {
    if (handle_ != VK_NULL_HANDLE) kDestroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
};

using VkBufferOwner = DeviceHandle<VkBuffer, vkDestroyBuffer>;
using VkMemoryOwner = DeviceHandle<VkDeviceMemory, vkFreeMemory>;
using VkImageOwner = DeviceHandle<VkImage, vkDestroyImage>;
using VkImageViewOwner = DeviceHandle<VkImageView, vkDestroyImageView>;
using VkShaderModuleOwner = DeviceHandle<VkShaderModule, vkDestroyShaderModule>;
using VkPipelineOwner = DeviceHandle<VkPipeline, vkDestroyPipeline>;
using VkPipelineLayoutOwner = DeviceHandle<VkPipelineLayout, vkDestroyPipelineLayout>;
using VkDescriptorSetLayoutOwner =
    DeviceHandle<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using VkDescriptorPoolOwner = DeviceHandle<VkDescriptorPool, vkDestroyDescriptorPool>;
using VkSamplerOwner = DeviceHandle<VkSampler, vkDestroySampler>;
using VkQueryPoolOwner = DeviceHandle<VkQueryPool, vkDestroyQueryPool>;
using VkCommandPoolOwner = DeviceHandle<VkCommandPool, vkDestroyCommandPool>;
using VkFenceOwner = DeviceHandle<VkFence, vkDestroyFence>;

// A zero-initialised Vulkan struct with its sType set (brace-initialising only sType
// trips -Wmissing-field-initializers).
template <class T>
T vkStruct(VkStructureType type) {
  T value{};
  value.sType = type;
  return value;
}

}  // namespace tb::gpu
