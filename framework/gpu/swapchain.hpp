#pragma once
// A window surface's swapchain: acquire an image, record into it, present.
// Knows nothing of what is drawn. Recreated on resize; a zero-sized surface
// (a minimized window) has no swapchain and acquire() returns nothing.
// One frame at a time: begin() waits for the previous frame's submission.
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include <shadelgraph/gpu/context.hpp>

namespace sg::gpu {

struct SwapchainImage {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  uint32_t index = 0;
};

class Swapchain {
 public:
  // Takes ownership of `surface` (made by the windowing code from the
  // context's instance). Throws GpuError naming what the device cannot do
  // with it (present from its graphics queue, a colour format, the usages).
  Swapchain(Context& context, VkSurfaceKHR surface, VkExtent2D size);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  // The window's framebuffer changed size: a new swapchain from the next acquire on.
  void resize(VkExtent2D size);
  // The next image and a command buffer begun for it; empty while the size is
  // zero. Waits for the previous frame's submission first.
  std::optional<SwapchainImage> acquire();
  VkCommandBuffer commandBuffer() const { return commandBuffer_; }
  // Ends the command buffer, submits it (after the acquire, on the graphics
  // queue) and presents the image; an out-of-date swapchain is recreated.
  void present(const SwapchainImage& image);
  // Waits until the last submission finished (e.g. before reading its results).
  void waitIdle();

  VkFormat format() const { return format_.format; }
  VkExtent2D extent() const { return extent_; }
  uint32_t imageCount() const { return uint32_t(images_.size()); }
  uint32_t minImageCount() const { return minImageCount_; }
  // Counts recreations: what was made per image (framebuffers) is stale when it changes.
  uint64_t generation() const { return generation_; }

 private:
  void create();
  void destroySwapchain();
  void release();  // everything, the surface last (the destructor, a failed constructor)

  Context& context_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSurfaceFormatKHR format_{};
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkExtent2D wanted_{}, extent_{};
  bool stale_ = true;
  uint32_t minImageCount_ = 2;
  uint64_t generation_ = 0;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkSemaphore> presentReady_;  // per image: a present waits on its own
  VkSemaphore acquired_ = VK_NULL_HANDLE;
  VkFence submitted_ = VK_NULL_HANDLE;
  bool pending_ = false;  // `submitted_` will be signalled
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;
};

}  // namespace sg::gpu
