// A Vulkan buffer in host-visible, coherent memory, mapped for its whole life. On
// lavapipe all memory is host memory; on a GPU this trades bandwidth for simplicity,
// which suits a harness that reads back everything it measures.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>

#include "core/gpu/vk_handle.h"

namespace tb::gpu {

class Context;

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& context, VkDeviceSize size_bytes, VkBufferUsageFlags usage);
  Buffer(Buffer&&) noexcept = default;
  Buffer& operator=(Buffer&&) noexcept = default;

  VkBuffer handle() const { return buffer_.get(); }
  VkDeviceSize sizeBytes() const { return size_bytes_; }
  std::byte* data() const { return mapped_; }

  template <class T>
  std::span<T> as() const {
    return {reinterpret_cast<T*>(mapped_), static_cast<size_t>(size_bytes_ / sizeof(T))};
  }
  // Copies in / out at offset_bytes; throws GpuError when out of range.
  void write(const void* src, size_t size_bytes, size_t offset_bytes = 0);
  void read(void* dst, size_t size_bytes, size_t offset_bytes = 0) const;

 private:
  VkMemoryOwner memory_;  // declared first so the buffer is destroyed before its memory
  VkBufferOwner buffer_;
  VkDeviceSize size_bytes_ = 0;
  std::byte* mapped_ = nullptr;
};

// `buffer` if it holds at least size_bytes, else a new one of max(size_bytes, 2x old).
void ensureCapacity(Context& context, Buffer& buffer, VkDeviceSize size_bytes,
                    VkBufferUsageFlags usage);

}  // namespace tb::gpu
