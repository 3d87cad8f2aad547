#pragma once
#include <string>

#include <shadelgraph/gpu/memory.hpp>

namespace sg::gpu {

struct ImageDesc {
  uint32_t width = 1, height = 1;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkImageUsageFlags usage = 0;
  uint32_t mipLevels = 1;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  bool concurrent = false;  // VK_SHARING_MODE_CONCURRENT over the context's queue families
  std::string name;
  std::string category = "image";
};

bool isDepthFormat(VkFormat format);
VkImageAspectFlags aspectOf(VkFormat format);

// A 2D VkImage with a view of all its mips. Either owns a sub-allocation
// (the allocator constructor) or is bound by someone else, as the render
// graph's executor does for aliased transients (bindMemory). Move-only.
class Image {
 public:
  Image() = default;
  Image(const Context& context, MemoryAllocator& memory, const ImageDesc& desc);
  // Unbound: call bindMemory before use.
  Image(const Context& context, const ImageDesc& desc);
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;

  VkMemoryRequirements memoryRequirements() const;
  void bindMemory(VkDeviceMemory memory, VkDeviceSize offset);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  const ImageDesc& desc() const { return desc_; }
  VkExtent2D extent() const { return {desc_.width, desc_.height}; }
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

 private:
  void createImage(const Context& context);
  void createView();
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  MemoryAllocator* memory_ = nullptr;
  ImageDesc desc_;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  Allocation allocation_;
};

}  // namespace sg::gpu
