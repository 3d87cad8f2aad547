#include "frame_presenter.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::app::view {
namespace {

void checkImgui(VkResult r) {
  if (r != VK_SUCCESS) throw gpu::GpuError("Dear ImGui's Vulkan backend: VkResult " + std::to_string(int(r)));
}

bool bgra(VkFormat f) { return f == VK_FORMAT_B8G8R8A8_UNORM; }

}  // namespace

FramePresenter::FramePresenter(gpu::Context& context, gpu::MemoryAllocator& memory, gpu::Swapchain& swapchain,
                               GLFWwindow* window)
    : context_(context), memory_(memory), swapchain_(swapchain) {
  const VkDevice device = context_.device();
  VkDescriptorPoolSize sizes{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 8};
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  pool.maxSets = 8;
  pool.poolSizeCount = 1;
  pool.pPoolSizes = &sizes;
  SG_VK(vkCreateDescriptorPool(device, &pool, nullptr, &descriptorPool_));
  createRenderPass();

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini beside wherever the viewer was started
  ImGui::StyleColorsDark();
  imguiGlfw_ = ImGui_ImplGlfw_InitForVulkan(window, true);
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = context_.instance();
  info.PhysicalDevice = context_.physicalDevice();
  info.Device = device;
  info.QueueFamily = context_.queue(gpu::Queue::Graphics).family;
  info.Queue = context_.queue(gpu::Queue::Graphics).queue;
  info.DescriptorPool = descriptorPool_;
  info.MinImageCount = std::max(2u, swapchain_.minImageCount());
  info.ImageCount = std::max(info.MinImageCount, 3u);
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = checkImgui;
  imguiVulkan_ = ImGui_ImplVulkan_Init(&info, renderPass_);
  if (!imguiGlfw_ || !imguiVulkan_) throw std::runtime_error("Dear ImGui's GLFW or Vulkan backend did not start");
  context_.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

FramePresenter::~FramePresenter() {
  swapchain_.waitIdle();
  if (imguiVulkan_) ImGui_ImplVulkan_Shutdown();
  if (imguiGlfw_) ImGui_ImplGlfw_Shutdown();
  if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
  const VkDevice device = context_.device();
  for (const VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  if (renderPass_) vkDestroyRenderPass(device, renderPass_, nullptr);
  if (descriptorPool_) vkDestroyDescriptorPool(device, descriptorPool_, nullptr);
}

// The UI pass loads the copied frame and leaves the image for a transfer (a window screenshot) or the present.
void FramePresenter::createRenderPass() {
  VkAttachmentDescription color{};
  color.format = swapchain_.format();
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkSubpassDependency after{};
  after.srcSubpass = 0;
  after.dstSubpass = VK_SUBPASS_EXTERNAL;
  after.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &color;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  SG_VK(vkCreateRenderPass(context_.device(), &info, nullptr, &renderPass_));
}

void FramePresenter::syncFramebuffers() {
  if (framebufferGeneration_ == swapchain_.generation()) return;
  const VkDevice device = context_.device();
  for (const VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  framebuffers_.assign(swapchain_.imageCount(), VK_NULL_HANDLE);
  framebufferGeneration_ = swapchain_.generation();
}

void FramePresenter::beginUi() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

bool FramePresenter::present(const gpu::HostImage& frame, bool drawUi, gpu::HostImage* windowPixels) {
  ImGui::Render();
  const auto image = swapchain_.acquire();
  if (!image) return false;
  syncFramebuffers();
  const VkExtent2D extent = swapchain_.extent();
  VkFramebuffer& framebuffer = framebuffers_[image->index];
  if (!framebuffer) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &image->view;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    SG_VK(vkCreateFramebuffer(context_.device(), &info, nullptr, &framebuffer));
  }
  // The frame's pixels in the swapchain's byte order.
  const VkDeviceSize bytes = VkDeviceSize(frame.width) * frame.height * 4;
  if (bytes && (!staging_ || staging_.size() < bytes))
    staging_ = gpu::Buffer(context_, memory_, {bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryLocation::Upload,
                                               "viewer frame upload", "viewer"});
  if (bytes) {
    std::byte* dst = staging_.mapped();
    std::memcpy(dst, frame.rgba8.data(), bytes);
    if (bgra(swapchain_.format()))
      for (VkDeviceSize i = 0; i < bytes; i += 4) std::swap(dst[i], dst[i + 2]);
  }

  const VkCommandBuffer cmd = swapchain_.commandBuffer();
  gpu::imageBarrier(cmd, image->image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT}, {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
  // Black where the frame does not reach (a resize the frame has not caught up with).
  if (frame.width < extent.width || frame.height < extent.height) {
    const VkClearColorValue black{{0.0f, 0.0f, 0.0f, 1.0f}};
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &all);
    gpu::imageBarrier(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                      {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
  }
  if (bytes) {
    VkBufferImageCopy region{};
    region.bufferRowLength = frame.width;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {std::min(frame.width, extent.width), std::min(frame.height, extent.height), 1};
    vkCmdCopyBufferToImage(cmd, staging_.handle(), image->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  }
  gpu::imageBarrier(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                    {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffer;
  begin.renderArea.extent = extent;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  if (drawUi) ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
  const VkDeviceSize windowBytes = VkDeviceSize(extent.width) * extent.height * 4;
  if (windowPixels) {
    if (!readback_ || readback_.size() < windowBytes)
      readback_ = gpu::Buffer(context_, memory_, {windowBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                  gpu::MemoryLocation::Readback, "viewer window readback", "viewer"});
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.handle(), 1, &region);
  }
  gpu::imageBarrier(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                    {VK_PIPELINE_STAGE_2_TRANSFER_BIT}, {VK_PIPELINE_STAGE_2_NONE});
  swapchain_.present(*image);
  if (windowPixels) {
    swapchain_.waitIdle();
    windowPixels->width = extent.width;
    windowPixels->height = extent.height;
    windowPixels->rgba8.resize(windowBytes);
    std::memcpy(windowPixels->rgba8.data(), readback_.mapped(), windowBytes);
    if (bgra(swapchain_.format()))
      for (size_t i = 0; i < windowBytes; i += 4) std::swap(windowPixels->rgba8[i], windowPixels->rgba8[i + 2]);
    for (size_t i = 3; i < windowBytes; i += 4) windowPixels->rgba8[i] = 255;  // the window is opaque
  }
  return true;
}

}  // namespace sg::app::view
