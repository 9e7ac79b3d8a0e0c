#include "core/gpu/device_info.h"

#include <cstring>

#include "core/gpu/vk_handle.h"

namespace tb::gpu {
namespace {

struct FeatureName {
  std::string_view name;
  bool DeviceFeatures::*member;
};

constexpr FeatureName kFeatureNames[] = {
    {"tessellationShader", &DeviceFeatures::tessellation_shader},
    {"geometryShader", &DeviceFeatures::geometry_shader},
    {"pipelineStatisticsQuery", &DeviceFeatures::pipeline_statistics_query},
    {"vertexPipelineStoresAndAtomics", &DeviceFeatures::vertex_pipeline_stores_and_atomics},
    {"transformFeedback", &DeviceFeatures::transform_feedback},
    {"shaderFloat64", &DeviceFeatures::shader_float64},
    {"dynamicRendering", &DeviceFeatures::dynamic_rendering},
    {"maintenance4", &DeviceFeatures::maintenance4},
    {"timestamps", &DeviceFeatures::timestamps},
    {"primitivesGeneratedQueryWithRasterizerDiscard", &DeviceFeatures::primitives_generated_query},
    {"pipelineExecutableInfo", &DeviceFeatures::pipeline_executable_info},
};

std::string_view deviceTypeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual_gpu";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

}  // namespace

DeviceFeatures tessCaptureFeatures() {
  DeviceFeatures f;
  f.tessellation_shader = true;
  f.transform_feedback = true;
  f.pipeline_statistics_query = true;
  f.dynamic_rendering = true;
  return f;
}

DeviceFeatures computeFeatures() {
  DeviceFeatures f;
  f.maintenance4 = true;
  return f;
}

std::vector<std::pair<std::string_view, bool>> featureList(const DeviceFeatures& features) {
  std::vector<std::pair<std::string_view, bool>> list;
  for (const FeatureName& f : kFeatureNames) list.emplace_back(f.name, features.*f.member);
  return list;
}

std::string firstMissingFeature(const DeviceFeatures& present, const DeviceFeatures& wanted) {
  for (const FeatureName& f : kFeatureNames) {
    if (wanted.*f.member && !(present.*f.member)) return std::string(f.name);
  }
  return {};
}

bool hasDeviceExtension(VkPhysicalDevice physical_device, const char* name) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(physical_device, nullptr, &count, extensions.data());
  for (const VkExtensionProperties& e : extensions) {
    if (std::strcmp(e.extensionName, name) == 0) return true;
  }
  return false;
}

std::string formatApiVersion(uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
         std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

DeviceFeatures queryDeviceFeatures(VkPhysicalDevice physical_device, uint32_t queue_family) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(physical_device, &properties);
  const bool is_13 = properties.apiVersion >= VK_API_VERSION_1_3;
  const bool has_xfb =
      hasDeviceExtension(physical_device, VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME);

  auto xfb = vkStruct<VkPhysicalDeviceTransformFeedbackFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT);
  auto v13 = vkStruct<VkPhysicalDeviceVulkan13Features>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES);
  auto features2 =
      vkStruct<VkPhysicalDeviceFeatures2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2);
  void** next = &features2.pNext;
  if (is_13) {
    *next = &v13;
    next = &v13.pNext;
  }
  if (has_xfb) {
    *next = &xfb;
    next = &xfb.pNext;
  }
  const bool has_pgq =
      hasDeviceExtension(physical_device, VK_EXT_PRIMITIVES_GENERATED_QUERY_EXTENSION_NAME);
  auto pgq = vkStruct<VkPhysicalDevicePrimitivesGeneratedQueryFeaturesEXT>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PRIMITIVES_GENERATED_QUERY_FEATURES_EXT);
  if (has_pgq) {
    *next = &pgq;
    next = &pgq.pNext;
  }
  const bool has_pep =
      hasDeviceExtension(physical_device, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
  auto pep = vkStruct<VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR);
  if (has_pep) *next = &pep;
  vkGetPhysicalDeviceFeatures2(physical_device, &features2);

  uint32_t family_count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &family_count, nullptr);
  std::vector<VkQueueFamilyProperties> families(family_count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_device, &family_count, families.data());

  DeviceFeatures f;
  const VkPhysicalDeviceFeatures& core = features2.features;
  f.tessellation_shader = core.tessellationShader;
  f.geometry_shader = core.geometryShader;
  f.pipeline_statistics_query = core.pipelineStatisticsQuery;
  f.vertex_pipeline_stores_and_atomics = core.vertexPipelineStoresAndAtomics;
  f.shader_float64 = core.shaderFloat64;
  f.transform_feedback = has_xfb && xfb.transformFeedback;
  f.dynamic_rendering = is_13 && v13.dynamicRendering;
  f.maintenance4 = is_13 && v13.maintenance4;
  f.primitives_generated_query =
      has_pgq && pgq.primitivesGeneratedQuery && pgq.primitivesGeneratedQueryWithRasterizerDiscard;
  f.pipeline_executable_info = has_pep && pep.pipelineExecutableInfo;
  f.timestamps = queue_family < family_count && families[queue_family].timestampValidBits > 0;
  return f;
}

DeviceInfo queryDeviceInfo(VkPhysicalDevice physical_device, uint32_t queue_family) {
  VkPhysicalDeviceProperties basic;
  vkGetPhysicalDeviceProperties(physical_device, &basic);
  // Driver properties are core from Vulkan 1.2; older devices report them empty.
  auto driver = vkStruct<VkPhysicalDeviceDriverProperties>(
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES);
  auto properties2 =
      vkStruct<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2);
  if (basic.apiVersion >= VK_API_VERSION_1_2) properties2.pNext = &driver;
  vkGetPhysicalDeviceProperties2(physical_device, &properties2);
  const VkPhysicalDeviceProperties& p = properties2.properties;

  DeviceInfo info;
  info.device_name = p.deviceName;
  info.device_type = deviceTypeName(p.deviceType);
  info.driver_name = driver.driverName;
  info.driver_info = driver.driverInfo;
  info.api_version = formatApiVersion(p.apiVersion);
  info.vendor_id = p.vendorID;
  info.device_id = p.deviceID;
  info.max_tessellation_level = p.limits.maxTessellationGenerationLevel;
  info.timestamp_period_ns = p.limits.timestampPeriod;
  info.features = queryDeviceFeatures(physical_device, queue_family);
  return info;
}

}  // namespace tb::gpu
