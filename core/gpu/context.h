// A headless Vulkan device: one graphics+compute queue, no surface. Prefers a
// discrete, then an integrated GPU, and falls back to lavapipe (CPU).
//
// Threads: one Context may be shared by several threads (the suite runs records
// concurrently). submitAndWait and attachment() are safe to call at once from several
// threads; submissions run one at a time (one queue, one command buffer). What an
// attachment holds is its own business: runPatchProgram is safe to call concurrently,
// the tessellator captures (tess_capture.h) serialise whole calls.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <typeindex>
#include <utility>
#include <vector>

#include "core/gpu/device_info.h"
#include "core/gpu/gpu_error.h"
#include "core/gpu/instance.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

struct ContextOptions {
  // Case-insensitive substring of the device name ("llvmpipe", "NVIDIA"); empty = best.
  std::string device_name;
  // Creation fails, naming the first absent one, unless all of these are present.
  DeviceFeatures required = tessCaptureFeatures();
  Validation validation = Validation::kAuto;
};

// The device a Context with these options would open, as results.json, timings.json and the
// benchmark JSON name it: "NAME (DRIVER_INFO, Vulkan X.Y.Z)", e.g. "llvmpipe (LLVM 15.0.6,
// 256 bits) (Mesa 22.3.6 (LLVM 15.0.6), Vulkan 1.3.230)"; "none: REASON" when there is none.
// Figures of two different strings are never compared (the device and its driver are part
// of a figure's identity).
std::string describeDevice(const std::string& device_name = {});
std::string describeDevice(const DeviceInfo& info);

// Every Vulkan device with a graphics+compute queue, best first: the order Context::create
// picks from, so the first is the default and `--device` names one by a substring. Empty,
// with *reason set, when there is none.
std::vector<DeviceInfo> listDevices(std::string* reason);

class Context {
 public:
  // Never throws for a missing device or feature: the error is one line naming it.
  static Expected<std::unique_ptr<Context>> create(const ContextOptions& options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const DeviceInfo& info() const { return info_; }
  const DeviceFeatures& features() const { return info_.features; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }
  VkInstance instance() const { return instance_->handle(); }
  VkPhysicalDevice physicalDevice() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queue_family_; }
  // Validation-layer errors so far; always 0 when the layer is not active.
  uint64_t validationErrorCount() const { return instance_->validationErrorCount(); }

  // Index of a memory type allowed by type_bits with all `required` flags, preferring
  // one that also has `preferred`. Throws GpuError if there is none.
  uint32_t memoryType(uint32_t type_bits, VkMemoryPropertyFlags required,
                      VkMemoryPropertyFlags preferred = 0) const;

  // Records `record` into a primary command buffer, submits it and waits for it.
  // Returns host seconds from vkQueueSubmit until the fence signals (the only honest
  // clock for tessellation draws on lavapipe). `record` must not call submit itself.
  // Thread-safe: concurrent callers take turns, each from recording to the fence.
  double submitAndWait(const std::function<void(VkCommandBuffer)>& record);

  // Throws GpuError naming the feature unless `wanted` are all enabled.
  void requireFeatures(const DeviceFeatures& wanted, const char* user) const;

  // A per-device object (pipeline cache and the like) created as T(Context&) on first
  // use and destroyed, latest first, before the device. Thread-safe; T guards its own
  // state when it is used from several threads.
  template <class T>
  T& attachment() {
    const std::lock_guard lock(attachments_mutex_);
    for (auto& [type, object] : attachments_) {
      if (type == std::type_index(typeid(T))) return *static_cast<T*>(object.get());
    }
    auto object = std::make_shared<T>(*this);
    T& ref = *object;
    attachments_.emplace_back(std::type_index(typeid(T)), std::move(object));
    return ref;
  }

 private:
  Context() = default;

  std::unique_ptr<Instance> instance_;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  DeviceInfo info_;
  VkPhysicalDeviceLimits limits_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  VkCommandPoolOwner command_pool_;
  VkCommandBuffer command_buffer_ = VK_NULL_HANDLE;
  VkFenceOwner fence_;
  std::mutex submit_mutex_;  // guards command_buffer_, fence_ and queue_
  std::mutex attachments_mutex_;
  std::vector<std::pair<std::type_index, std::shared_ptr<void>>> attachments_;
};

}  // namespace tb::gpu
