#pragma once
// The viewer's GLFW window: no display is one error line, input arrives as
// InputEvents (those Dear ImGui wants stay with it), and a Vulkan surface is
// made for the swapchain.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "input_event.hpp"

struct GLFWwindow;

namespace sg::app::view {

class ViewerWindow {
 public:
  // Starts GLFW (throws "no display ..." without one) and opens a window of
  // `width` x `height` framebuffer pixels, without a client API.
  ViewerWindow(const std::string& title, uint32_t width, uint32_t height);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  // The instance extensions GLFW needs for a surface (before the context exists).
  static std::vector<std::string> requiredInstanceExtensions();
  VkSurfaceKHR createSurface(VkInstance instance);

  // Polls the window system; the events since the last call.
  std::vector<InputEvent> poll();
  bool closeRequested() const;
  VkExtent2D framebufferSize() const;
  bool minimized() const;
  void setSize(uint32_t width, uint32_t height);
  // Asks the window manager to iconify (or restore) the window; it answers asynchronously.
  void setIconified(bool iconified);
  GLFWwindow* handle() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
  std::vector<InputEvent> events_;
};

}  // namespace sg::app::view
