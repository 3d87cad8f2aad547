#pragma once
// Puts the viewer's frame on the window: the renderer's image (read back, as
// render writes it) copied into the swapchain image, Dear ImGui drawn over it
// (its GLFW and Vulkan backends, from Debian's libimgui-dev), presented.
#include <optional>
#include <vector>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/readback.hpp>
#include <shadelgraph/gpu/swapchain.hpp>

struct GLFWwindow;

namespace sg::app::view {

class FramePresenter {
 public:
  FramePresenter(gpu::Context& context, gpu::MemoryAllocator& memory, gpu::Swapchain& swapchain, GLFWwindow* window);
  ~FramePresenter();
  FramePresenter(const FramePresenter&) = delete;
  FramePresenter& operator=(const FramePresenter&) = delete;

  // Starts Dear ImGui's frame: panels are built between this and present().
  void beginUi();
  // Shows `frame` with the panels over it (unless !drawUi). windowPixels: also
  // read back what was presented. False when nothing was shown (minimized).
  bool present(const gpu::HostImage& frame, bool drawUi, gpu::HostImage* windowPixels = nullptr);

 private:
  void createRenderPass();
  void syncFramebuffers();

  gpu::Context& context_;
  gpu::MemoryAllocator& memory_;
  gpu::Swapchain& swapchain_;
  VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  std::vector<VkFramebuffer> framebuffers_;
  uint64_t framebufferGeneration_ = ~0ull;
  gpu::Buffer staging_, readback_;
  bool imguiVulkan_ = false, imguiGlfw_ = false;
};

}  // namespace sg::app::view
