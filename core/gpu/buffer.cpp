#include "core/gpu/buffer.h"

#include <algorithm>
#include <cstring>

#include "core/gpu/context.h"
#include "core/gpu/vk_handle.h"

namespace tb::gpu {

Buffer::Buffer(Context& context, VkDeviceSize size_bytes, VkBufferUsageFlags usage)
    : size_bytes_(size_bytes) {
  const VkDevice device = context.device();
  auto info = vkStruct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
  info.size = std::max<VkDeviceSize>(size_bytes, 4);
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  vkCheck(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
  buffer_ = VkBufferOwner(device, buffer);

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  auto alloc = vkStruct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
  alloc.allocationSize = requirements.size;
  // Cached memory makes host readback fast; coherent spares us flush/invalidate.
  alloc.memoryTypeIndex =
      context.memoryType(requirements.memoryTypeBits,
                         VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                         VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  vkCheck(vkAllocateMemory(device, &alloc, nullptr, &memory), "vkAllocateMemory");
  memory_ = VkMemoryOwner(device, memory);
  vkCheck(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
  void* mapped = nullptr;
  vkCheck(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  mapped_ = static_cast<std::byte*>(mapped);
}

void Buffer::write(const void* src, size_t size_bytes, size_t offset_bytes) {
  if (offset_bytes + size_bytes > size_bytes_) throw GpuError("Buffer::write out of range");
  if (size_bytes > 0) std::memcpy(mapped_ + offset_bytes, src, size_bytes);
}

void Buffer::read(void* dst, size_t size_bytes, size_t offset_bytes) const {
  if (offset_bytes + size_bytes > size_bytes_) throw GpuError("Buffer::read out of range");
  if (size_bytes > 0) std::memcpy(dst, mapped_ + offset_bytes, size_bytes);
}

void ensureCapacity(Context& context, Buffer& buffer, VkDeviceSize size_bytes,
                    VkBufferUsageFlags usage) {
  if (buffer.handle() != VK_NULL_HANDLE && buffer.sizeBytes() >= size_bytes) return;
  buffer = Buffer(context, std::max(size_bytes, 2 * buffer.sizeBytes()), usage);
}

}  // namespace tb::gpu
