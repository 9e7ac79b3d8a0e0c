// The Vulkan instance: no surface and no instance extensions, except VK_EXT_debug_utils
// when validation is on (then a messenger counts validation errors for the tests).
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <memory>

#include "core/gpu/gpu_error.h"

namespace tb::gpu {

enum class Validation {
  kAuto,  // on in Debug builds or when env TB_VK_VALIDATION=1; off when it is 0
  kOn,    // on if VK_LAYER_KHRONOS_validation is installed
  kOff,
};

class Instance {
 public:
  static Expected<std::unique_ptr<Instance>> create(Validation validation);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  VkInstance handle() const { return instance_; }
  bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
  // Messages of severity error / warning the validation layer reported so far.
  uint64_t validationErrorCount() const { return counts_->errors.load(); }
  uint64_t validationWarningCount() const { return counts_->warnings.load(); }

  struct MessageCounts {
    std::atomic<uint64_t> errors{0};
    std::atomic<uint64_t> warnings{0};
  };

 private:
  Instance() = default;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  std::unique_ptr<MessageCounts> counts_ = std::make_unique<MessageCounts>();
};

// Whether `validation` asks for the layer in this build and environment.
bool validationRequested(Validation validation);

}  // namespace tb::gpu
