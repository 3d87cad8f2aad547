#include <shadelgraph/gpu/buffer.hpp>

#include <utility>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {

Buffer::Buffer(const Context& context, MemoryAllocator& memory, const BufferDesc& desc) : memory_(&memory) {
  create(context, desc);
  allocation_ = memory.allocate(memoryRequirements(), desc.location, desc.category);
  bindMemory(allocation_.memory, allocation_.offset);
}

Buffer::Buffer(const Context& context, const BufferDesc& desc) { create(context, desc); }

void Buffer::create(const Context& context, const BufferDesc& desc) {
  device_ = context.device();
  size_ = desc.size;
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = desc.size;
  info.usage = desc.usage | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  const std::vector<uint32_t> families = context.queueFamilies();
  if (desc.concurrent && families.size() > 1) {
    info.sharingMode = VK_SHARING_MODE_CONCURRENT;
    info.queueFamilyIndexCount = static_cast<uint32_t>(families.size());
    info.pQueueFamilyIndices = families.data();
  }
  SG_VK(vkCreateBuffer(device_, &info, nullptr, &buffer_));
  context.setDebugName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<uint64_t>(buffer_), desc.name.c_str());
}

VkMemoryRequirements Buffer::memoryRequirements() const {
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, buffer_, &req);
  return req;
}

void Buffer::bindMemory(VkDeviceMemory memory, VkDeviceSize offset) {
  SG_VK(vkBindBufferMemory(device_, buffer_, memory, offset));
  VkBufferDeviceAddressInfo addr{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
  addr.buffer = buffer_;
  address_ = vkGetBufferDeviceAddress(device_, &addr);
}

VkBufferView Buffer::texelView(const Context& context, VkFormat format, uint32_t texelBytes) const {
  for (const auto& [f, view] : views_)
    if (f == format) return view.handle();
  views_.emplace_back(format, BufferView(context, buffer_, size_, format, texelBytes, "texel view"));
  return views_.back().second.handle();
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& o) noexcept { *this = std::move(o); }

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    release();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, nullptr);
    buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
    size_ = std::exchange(o.size_, 0);
    address_ = std::exchange(o.address_, 0);
    allocation_ = std::exchange(o.allocation_, Allocation{});
    views_ = std::exchange(o.views_, {});
  }
  return *this;
}

void Buffer::release() {
  views_.clear();
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) memory_->free(allocation_);
  buffer_ = VK_NULL_HANDLE;
}

}  // namespace sg::gpu
