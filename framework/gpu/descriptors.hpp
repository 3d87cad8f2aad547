#pragma once
// Descriptor sets for one frame: allocated from a pool that is reset as a
// whole when the frame's work is done (no per-set bookkeeping, works on every
// Vulkan 1.3 device, unlike push descriptors).
#include <initializer_list>
#include <span>
#include <variant>

#include <vulkan/vulkan.h>

namespace sg::gpu {

class Context;
class Pipeline;

struct BufferBinding {
  VkBuffer buffer;
  VkDeviceSize offset = 0;
  VkDeviceSize range = VK_WHOLE_SIZE;
};
struct ImageBinding {
  VkImageView view;
  VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
  VkSampler sampler = VK_NULL_HANDLE;
};
// A uniform texel buffer (gpu::BufferView).
struct TexelBufferBinding {
  VkBufferView view;
};
struct DescriptorWrite {
  uint32_t binding;
  std::variant<BufferBinding, ImageBinding, TexelBufferBinding> resource;
};

class DescriptorArena {
 public:
  explicit DescriptorArena(const Context& context, uint32_t maxSets = 1024);
  ~DescriptorArena();
  DescriptorArena(const DescriptorArena&) = delete;
  DescriptorArena& operator=(const DescriptorArena&) = delete;

  // Allocates a set for the pipeline's set-0 layout, writes it (descriptor
  // types come from the pipeline's bindings) and binds it.
  void bind(VkCommandBuffer cmd, const Pipeline& pipeline, std::span<const DescriptorWrite> writes);
  void bind(VkCommandBuffer cmd, const Pipeline& pipeline, std::initializer_list<DescriptorWrite> writes) {
    bind(cmd, pipeline, std::span<const DescriptorWrite>(writes.begin(), writes.size()));
  }
  void reset();

 private:
  VkDevice device_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

}  // namespace sg::gpu
