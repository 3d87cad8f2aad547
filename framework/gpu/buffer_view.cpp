#include <shadelgraph/gpu/buffer_view.hpp>

#include <string>
#include <utility>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {

BufferView::BufferView(const Context& context, VkBuffer buffer, VkDeviceSize bufferBytes, VkFormat format,
                       uint32_t texelBytes, const char* name)
    : device_(context.device()) {
  const VkDeviceSize texels = bufferBytes / texelBytes;
  const uint32_t limit = context.properties().limits.maxTexelBufferElements;
  if (texels > limit)
    throw GpuError(std::string(name) + ": " + std::to_string(texels) + " texels, more than the device's " +
                   "maxTexelBufferElements (" + std::to_string(limit) + ")");
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer;
  info.format = format;
  info.offset = 0;
  info.range = texels * texelBytes;  // whole texels only (a trailing partial one is not addressable)
  SG_VK(vkCreateBufferView(device_, &info, nullptr, &view_));
  context.setDebugName(VK_OBJECT_TYPE_BUFFER_VIEW, reinterpret_cast<uint64_t>(view_), name);
}

BufferView::~BufferView() { release(); }

BufferView::BufferView(BufferView&& o) noexcept { *this = std::move(o); }

BufferView& BufferView::operator=(BufferView&& o) noexcept {
  if (this != &o) {
    release();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    view_ = std::exchange(o.view_, VK_NULL_HANDLE);
  }
  return *this;
}

void BufferView::release() {
  if (view_ != VK_NULL_HANDLE) vkDestroyBufferView(device_, view_, nullptr);
  view_ = VK_NULL_HANDLE;
}

}  // namespace sg::gpu
