#include "core/gpu/compiler_device.h"

#include <vector>

#include "core/gpu/vk_handle.h"

namespace tb::gpu {

Expected<std::unique_ptr<CompilerDevice>> CompilerDevice::create() {
  using Result = Expected<std::unique_ptr<CompilerDevice>>;
  Expected<std::unique_ptr<Instance>> instance = Instance::create(Validation::kOff);
  if (!instance) return Result::failure(instance.error());
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance.value()->handle(), &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance.value()->handle(), &count, devices.data());
  if (devices.empty()) return Result::failure("no Vulkan device");
  const VkPhysicalDevice physical = devices.front();
  std::unique_ptr<CompilerDevice> made(new CompilerDevice);
  made->info_ = queryDeviceInfo(physical, 0);
  const DeviceFeatures& f = made->info_.features;
  if (!f.pipeline_executable_info) {
    return Result::failure(made->info_.device_name +
                           " has no VK_KHR_pipeline_executable_properties");
  }
  if (!f.tessellation_shader || !f.dynamic_rendering) {
    return Result::failure(made->info_.device_name + " lacks tessellation or dynamic rendering");
  }
  auto pep = vkStruct<VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR);
  pep.pipelineExecutableInfo = VK_TRUE;
  auto v13 = vkStruct<VkPhysicalDeviceVulkan13Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  v13.dynamicRendering = VK_TRUE;
  v13.maintenance4 = f.maintenance4;
  v13.pNext = &pep;
  auto features2 =
      vkStruct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  features2.pNext = &v13;
  features2.features.tessellationShader = VK_TRUE;
  features2.features.vertexPipelineStoresAndAtomics = f.vertex_pipeline_stores_and_atomics;
  features2.features.shaderFloat64 = f.shader_float64;
  features2.features.geometryShader = f.geometry_shader;
  const char* extensions[] = {VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME};
  const float priority = 1.0f;
  auto queue = vkStruct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
  queue.queueFamilyIndex = 0;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  auto info = vkStruct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
  info.pNext = &features2;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = extensions;
  const VkResult result = vkCreateDevice(physical, &info, nullptr, &made->device_);
  if (result != VK_SUCCESS) {
    made->device_ = VK_NULL_HANDLE;
    return Result::failure("vkCreateDevice on " + made->info_.device_name + " failed (" +
                           std::to_string(int(result)) + ")");
  }
  made->instance_ = std::move(instance.value());
  return made;
}

CompilerDevice::~CompilerDevice() {
  if (device_ != VK_NULL_HANDLE) vkDestroyDevice(device_, nullptr);
}

}  // namespace tb::gpu
