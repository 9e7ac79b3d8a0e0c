// What a Vulkan device is and offers, in a form reports can print.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tb::gpu {

// The optional features tessbench uses. Context enables every one that is present.
struct DeviceFeatures {
  bool tessellation_shader = false;
  bool geometry_shader = false;
  bool pipeline_statistics_query = false;           // TCS patches, TES invocations, clipping
  bool vertex_pipeline_stores_and_atomics = false;  // SSBO capture from the TES
  bool transform_feedback = false;                  // VK_EXT_transform_feedback
  bool shader_float64 = false;
  bool dynamic_rendering = false;  // Vulkan 1.3
  bool maintenance4 = false;       // Vulkan 1.3; glslang's vulkan1.3 compute uses LocalSizeId
  bool timestamps = false;         // graphics+compute queue timestamps (timestampValidBits > 0)
  // VK_EXT_primitives_generated_query with rasterizer discard: the triangles the
  // tessellator emits, counted by the device (patch programs run with discard).
  bool primitives_generated_query = false;
  // VK_KHR_pipeline_executable_properties: the driver's statistics and assembly of each
  // compiled pipeline executable (pipeline_executables.h).
  bool pipeline_executable_info = false;
};

// Features the tessellation capture path (tess_capture.h) cannot do without.
DeviceFeatures tessCaptureFeatures();
// Features the compute path (compute.h) cannot do without.
DeviceFeatures computeFeatures();

// Every feature with its Vulkan name ("tessellationShader", ...) and whether it is set.
std::vector<std::pair<std::string_view, bool>> featureList(const DeviceFeatures& features);

// Vulkan name of the first feature set in `wanted` but not in `present`; empty if none.
std::string firstMissingFeature(const DeviceFeatures& present, const DeviceFeatures& wanted);

struct DeviceInfo {
  std::string device_name;  // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string device_type;  // "discrete_gpu", "integrated_gpu", "virtual_gpu", "cpu", "other"
  std::string driver_name;  // e.g. "llvmpipe"
  std::string driver_info;  // e.g. "Mesa 22.3.6 (LLVM 15.0.6)"
  std::string api_version;  // device's Vulkan version, "major.minor.patch"
  uint32_t vendor_id = 0;
  uint32_t device_id = 0;
  uint32_t max_tessellation_level = 0;  // maxTessellationGenerationLevel; 64 on lavapipe
  double timestamp_period_ns = 0;       // nanoseconds per timestamp tick
  DeviceFeatures features;              // present on the device, and enabled
  bool validation_enabled = false;      // VK_LAYER_KHRONOS_validation is active
};

// Queried from the driver; features that need Vulkan 1.3 count as absent below 1.3.
DeviceFeatures queryDeviceFeatures(VkPhysicalDevice physical_device, uint32_t queue_family);
DeviceInfo queryDeviceInfo(VkPhysicalDevice physical_device, uint32_t queue_family);

bool hasDeviceExtension(VkPhysicalDevice physical_device, const char* name);

// "1.3.230"
std::string formatApiVersion(uint32_t version);

}  // namespace tb::gpu
