#pragma once
// A typed view of a buffer (a uniform texel buffer in GLSL: samplerBuffer,
// texelFetch). On CPU devices (lavapipe) a texel fetch is one gather across
// the lanes, where a storage-buffer read with per-lane addresses is a loop
// over the lanes with a branch and a bounds check each. Move-only.
#include <vulkan/vulkan.h>

namespace sg::gpu {

class Context;

class BufferView {
 public:
  BufferView() = default;
  // Views the whole buffer as texels of `format`; throws if it holds more than
  // the device's maxTexelBufferElements.
  BufferView(const Context& context, VkBuffer buffer, VkDeviceSize bufferBytes, VkFormat format, uint32_t texelBytes,
             const char* name);
  ~BufferView();
  BufferView(BufferView&& other) noexcept;
  BufferView& operator=(BufferView&& other) noexcept;

  VkBufferView handle() const { return view_; }
  explicit operator bool() const { return view_ != VK_NULL_HANDLE; }

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBufferView view_ = VK_NULL_HANDLE;
};

}  // namespace sg::gpu
