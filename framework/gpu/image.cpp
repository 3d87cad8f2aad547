#include <shadelgraph/gpu/image.hpp>

#include <utility>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {

bool isDepthFormat(VkFormat f) {
  return f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D16_UNORM ||
         f == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

VkImageAspectFlags aspectOf(VkFormat f) {
  if (f == VK_FORMAT_D24_UNORM_S8_UINT || f == VK_FORMAT_D32_SFLOAT_S8_UINT)
    return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
  return isDepthFormat(f) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

Image::Image(const Context& context, MemoryAllocator& memory, const ImageDesc& desc)
    : device_(context.device()), memory_(&memory), desc_(desc) {
  createImage(context);
  allocation_ = memory.allocate(memoryRequirements(), MemoryLocation::Device, desc.category);
  SG_VK(vkBindImageMemory(device_, image_, allocation_.memory, allocation_.offset));
  createView();
}

Image::Image(const Context& context, const ImageDesc& desc) : device_(context.device()), desc_(desc) {
  createImage(context);
}

void Image::createImage(const Context& context) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc_.format;
  info.extent = {desc_.width, desc_.height, 1};
  info.mipLevels = desc_.mipLevels;
  info.arrayLayers = 1;
  info.samples = desc_.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc_.usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  const std::vector<uint32_t> families = context.queueFamilies();
  if (desc_.concurrent && families.size() > 1) {
    info.sharingMode = VK_SHARING_MODE_CONCURRENT;
    info.queueFamilyIndexCount = static_cast<uint32_t>(families.size());
    info.pQueueFamilyIndices = families.data();
  }
  SG_VK(vkCreateImage(device_, &info, nullptr, &image_));
  context.setDebugName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<uint64_t>(image_), desc_.name.c_str());
}

VkMemoryRequirements Image::memoryRequirements() const {
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device_, image_, &req);
  return req;
}

void Image::bindMemory(VkDeviceMemory memory, VkDeviceSize offset) {
  SG_VK(vkBindImageMemory(device_, image_, memory, offset));
  createView();
}

void Image::createView() {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image_;
  info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  info.format = desc_.format;
  info.subresourceRange = {aspectOf(desc_.format), 0, desc_.mipLevels, 0, 1};
  SG_VK(vkCreateImageView(device_, &info, nullptr, &view_));
}

Image::~Image() { release(); }

Image::Image(Image&& o) noexcept { *this = std::move(o); }

Image& Image::operator=(Image&& o) noexcept {
  if (this != &o) {
    release();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, nullptr);
    desc_ = std::move(o.desc_);
    image_ = std::exchange(o.image_, VK_NULL_HANDLE);
    view_ = std::exchange(o.view_, VK_NULL_HANDLE);
    allocation_ = std::exchange(o.allocation_, Allocation{});
  }
  return *this;
}

void Image::release() {
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  if (memory_) memory_->free(allocation_);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
}

}  // namespace sg::gpu
