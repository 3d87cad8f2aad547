#include <shadelgraph/gpu/swapchain.hpp>

#include <algorithm>
#include <string>

#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {
namespace {

// 8-bit UNORM: the frame's bytes are already sRGB-encoded and are copied as they are.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
  uint32_t n = 0;
  SG_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(n);
  SG_VK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &n, formats.data()));
  for (const VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const auto& f : formats)
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  throw GpuError("window surface: no B8G8R8A8_UNORM or R8G8B8A8_UNORM format with the sRGB colour space");
}

constexpr VkImageUsageFlags kUsage =
    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

}  // namespace

Swapchain::Swapchain(Context& context, VkSurfaceKHR surface, VkExtent2D size)
    : context_(context), surface_(surface), wanted_(size) {
  try {
    VkBool32 presentable = VK_FALSE;
    const uint32_t family = context_.queue(Queue::Graphics).family;
    SG_VK(vkGetPhysicalDeviceSurfaceSupportKHR(context_.physicalDevice(), family, surface_, &presentable));
    if (!presentable)
      throw GpuError("window surfaces unsupported: " + context_.deviceName() + " cannot present from its graphics queue");
    VkSurfaceCapabilitiesKHR caps;
    SG_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice(), surface_, &caps));
    if ((caps.supportedUsageFlags & kUsage) != kUsage)
      throw GpuError("window surface: swapchain images cannot be colour attachments and transfer sources and destinations");
    format_ = chooseFormat(context_.physicalDevice(), surface_);
    const VkDevice device = context_.device();
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    SG_VK(vkCreateSemaphore(device, &semaphore, nullptr, &acquired_));
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    SG_VK(vkCreateFence(device, &fence, nullptr, &submitted_));
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = family;
    SG_VK(vkCreateCommandPool(device, &pool, nullptr, &pool_));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    SG_VK(vkAllocateCommandBuffers(device, &alloc, &commandBuffer_));
  } catch (...) {
    release();
    throw;
  }
}

Swapchain::~Swapchain() { release(); }

void Swapchain::release() {
  const VkDevice device = context_.device();
  waitIdle();
  // Presentation may still wait on the semaphores the last submission signalled.
  SG_VK(vkDeviceWaitIdle(device));
  destroySwapchain();
  if (pool_) vkDestroyCommandPool(device, pool_, nullptr);
  if (submitted_) vkDestroyFence(device, submitted_, nullptr);
  if (acquired_) vkDestroySemaphore(device, acquired_, nullptr);
  pool_ = VK_NULL_HANDLE;
  submitted_ = VK_NULL_HANDLE;
  acquired_ = VK_NULL_HANDLE;
  if (surface_) vkDestroySurfaceKHR(context_.instance(), surface_, nullptr);
  surface_ = VK_NULL_HANDLE;
}

void Swapchain::waitIdle() {
  if (!pending_) return;
  SG_VK(vkWaitForFences(context_.device(), 1, &submitted_, VK_TRUE, UINT64_MAX));
  SG_VK(vkResetFences(context_.device(), 1, &submitted_));
  pending_ = false;
}

void Swapchain::destroySwapchain() {
  const VkDevice device = context_.device();
  for (const VkSemaphore s : presentReady_) vkDestroySemaphore(device, s, nullptr);
  for (const VkImageView v : views_) vkDestroyImageView(device, v, nullptr);
  presentReady_.clear();
  views_.clear();
  images_.clear();
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
}

void Swapchain::resize(VkExtent2D size) {
  if (size.width == wanted_.width && size.height == wanted_.height && swapchain_) return;
  wanted_ = size;
  stale_ = true;
}

void Swapchain::create() {
  waitIdle();
  // The queue may still present the old images: let it finish before they go.
  SG_VK(vkQueueWaitIdle(context_.queue(Queue::Graphics).queue));
  destroySwapchain();
  VkSurfaceCapabilitiesKHR caps;
  SG_VK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physicalDevice(), surface_, &caps));
  extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : wanted_;
  extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent_.height = std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  stale_ = false;
  if (extent_.width == 0 || extent_.height == 0) return;  // minimized
  minImageCount_ = std::max(2u, caps.minImageCount);
  if (caps.maxImageCount) minImageCount_ = std::min(minImageCount_, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = minImageCount_;
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = kUsage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // the one every device has
  info.clipped = VK_TRUE;
  const VkDevice device = context_.device();
  SG_VK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_));
  uint32_t n = 0;
  SG_VK(vkGetSwapchainImagesKHR(device, swapchain_, &n, nullptr));
  images_.resize(n);
  SG_VK(vkGetSwapchainImagesKHR(device, swapchain_, &n, images_.data()));
  for (const VkImage image : images_) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_.format;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    SG_VK(vkCreateImageView(device, &view, nullptr, &views_.emplace_back()));
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    SG_VK(vkCreateSemaphore(device, &semaphore, nullptr, &presentReady_.emplace_back()));
  }
  ++generation_;
}

std::optional<SwapchainImage> Swapchain::acquire() {
  waitIdle();
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (stale_) create();
    if (!swapchain_) return std::nullopt;
    uint32_t index = 0;
    const VkResult r = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
      stale_ = true;
      continue;
    }
    if (r != VK_SUBOPTIMAL_KHR) SG_VK(r);
    SG_VK(vkResetCommandBuffer(commandBuffer_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    SG_VK(vkBeginCommandBuffer(commandBuffer_, &begin));
    return SwapchainImage{images_[index], views_[index], index};
  }
  return std::nullopt;
}

void Swapchain::present(const SwapchainImage& image) {
  SG_VK(vkEndCommandBuffer(commandBuffer_));
  const VkQueue queue = context_.queue(Queue::Graphics).queue;
  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = acquired_;
  wait.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = presentReady_[image.index];
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cmd{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmd.commandBuffer = commandBuffer_;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmd;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  SG_VK(vkQueueSubmit2(queue, 1, &submit, submitted_));
  pending_ = true;
  VkPresentInfoKHR present{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  present.waitSemaphoreCount = 1;
  present.pWaitSemaphores = &presentReady_[image.index];
  present.swapchainCount = 1;
  present.pSwapchains = &swapchain_;
  present.pImageIndices = &image.index;
  const VkResult r = vkQueuePresentKHR(queue, &present);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR)
    stale_ = true;
  else
    SG_VK(r);
}

}  // namespace sg::gpu
