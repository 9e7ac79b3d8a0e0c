// Errors of the Vulkan layer. Expected<T> carries a one-line reason for outcomes a
// caller should handle (no device, a missing feature); GpuError is thrown for a
// Vulkan call that fails on a device that was usable, which is a bug or a lost device.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace tb::gpu {

class GpuError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <class T>
class Expected {
 public:
  Expected(T value) : value_(std::move(value)) {}  // NOLINT: implicit by design
  static Expected failure(std::string reason) {
    Expected e;
    e.error_ = std::move(reason);
    return e;
  }

  explicit operator bool() const { return value_.has_value(); }
  bool ok() const { return value_.has_value(); }
  T& value() { return *value_; }
  const T& value() const { return *value_; }
  T* operator->() { return &*value_; }
  T& operator*() { return *value_; }
  // One line naming what is missing; empty when ok().
  const std::string& error() const { return error_; }

 private:
  Expected() = default;
  std::optional<T> value_;
  std::string error_;
};

// "VK_ERROR_DEVICE_LOST" etc.
const char* vkResultName(VkResult result);

// Throws GpuError("<what>: <VkResult name>") unless result is VK_SUCCESS.
void vkCheck(VkResult result, const char* what);

}  // namespace tb::gpu
