// A Vulkan device made only to compile pipelines and read what the driver's compiler made
// of them (pipeline_executables.h): no queue is used, no memory allocated, nothing executed.
// RADV's null device (RADV_FORCE_FAMILY without an AMD GPU) is such a device; a Context
// (which makes a queue, a command pool and fences) cannot be made on it.
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>

#include "core/gpu/device_info.h"
#include "core/gpu/gpu_error.h"
#include "core/gpu/instance.h"

namespace tb::gpu {

class CompilerDevice {
 public:
  // The first device the environment's drivers give, with the stages and features the
  // suite's pipelines use and VK_KHR_pipeline_executable_properties; a failure names what is
  // missing.
  static Expected<std::unique_ptr<CompilerDevice>> create();
  ~CompilerDevice();
  CompilerDevice(const CompilerDevice&) = delete;
  CompilerDevice& operator=(const CompilerDevice&) = delete;

  VkDevice device() const { return device_; }
  const DeviceInfo& info() const { return info_; }

 private:
  CompilerDevice() = default;
  std::unique_ptr<Instance> instance_;
  VkDevice device_ = VK_NULL_HANDLE;
  DeviceInfo info_;
};

}  // namespace tb::gpu
