#pragma once
#include <cstring>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <shadelgraph/gpu/buffer_view.hpp>
#include <shadelgraph/gpu/memory.hpp>

namespace sg::gpu {

struct BufferDesc {
  VkDeviceSize size = 0;
  VkBufferUsageFlags usage = 0;
  MemoryLocation location = MemoryLocation::Device;
  std::string name;
  std::string category = "buffer";  // memory report bucket
  bool concurrent = false;          // VK_SHARING_MODE_CONCURRENT over the context's queue families
};

// A VkBuffer with its own sub-allocation. Move-only.
class Buffer {
 public:
  Buffer() = default;
  Buffer(const Context& context, MemoryAllocator& memory, const BufferDesc& desc);
  // Unbound: call bindMemory before use (the render graph's aliased transients).
  Buffer(const Context& context, const BufferDesc& desc);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;

  VkMemoryRequirements memoryRequirements() const;
  void bindMemory(VkDeviceMemory memory, VkDeviceSize offset);

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  VkDeviceAddress address() const { return address_; }
  std::byte* mapped() const { return allocation_.mapped; }
  template <class T>
  std::span<T> view() const {
    return {reinterpret_cast<T*>(allocation_.mapped), size_ / sizeof(T)};
  }
  void write(const void* data, size_t bytes, size_t offset = 0) { std::memcpy(mapped() + offset, data, bytes); }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
  // The whole buffer as texels of `format` (a uniform texel buffer; the
  // buffer needs VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT and bound memory),
  // made on first use and kept as long as the buffer: the render graph's
  // buffers live across frames.
  VkBufferView texelView(const Context& context, VkFormat format, uint32_t texelBytes) const;

 private:
  void create(const Context& context, const BufferDesc& desc);
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  MemoryAllocator* memory_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  VkDeviceAddress address_ = 0;
  Allocation allocation_;
  mutable std::vector<std::pair<VkFormat, BufferView>> views_;  // texelView's, destroyed before the buffer
};

}  // namespace sg::gpu
