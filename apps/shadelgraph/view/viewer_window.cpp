#include "viewer_window.hpp"

#include <stdexcept>
#include <string>

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace sg::app::view {
namespace {

std::string gLastGlfwError;

void onGlfwError(int, const char* description) { gLastGlfwError = description ? description : "unknown GLFW error"; }

ViewerWindow* self(GLFWwindow* w) { return static_cast<ViewerWindow*>(glfwGetWindowUserPointer(w)); }

// Input Dear ImGui is using (a panel under the cursor, a focused field) is not the viewer's.
bool imguiWantsMouse() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse; }
bool imguiWantsKeyboard() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard; }

CursorPosition cursorPixel(GLFWwindow* w, double x, double y) {
  int ww = 0, wh = 0, fw = 0, fh = 0;
  glfwGetWindowSize(w, &ww, &wh);
  glfwGetFramebufferSize(w, &fw, &fh);
  return framebufferPixel(x, y, ww, wh, fw, fh);
}

}  // namespace


ViewerWindow::ViewerWindow(const std::string& title, uint32_t width, uint32_t height) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) throw std::runtime_error("no display: the window system did not start (" + gLastGlfwError + ")");
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw std::runtime_error("window surfaces unsupported: GLFW found no Vulkan loader with surface support");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw std::runtime_error("no display: cannot open a window (" + gLastGlfwError + ")");
  }
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_REPEAT || key == GLFW_KEY_UNKNOWN) return;
    if (action == GLFW_PRESS && imguiWantsKeyboard()) return;
    InputEvent e{action == GLFW_PRESS ? InputEvent::Type::KeyDown : InputEvent::Type::KeyUp};
    e.key = key;
    self(w)->events_.push_back(e);
  });
  glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
    InputEvent e{InputEvent::Type::MouseMove};
    const CursorPosition p = cursorPixel(w, x, y);
    e.x = p.x;
    e.y = p.y;
    self(w)->events_.push_back(e);
  });
  glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
    if (action == GLFW_PRESS && imguiWantsMouse()) return;
    InputEvent e{action == GLFW_PRESS ? InputEvent::Type::ButtonDown : InputEvent::Type::ButtonUp};
    e.button = button;
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(w, &x, &y);
    const CursorPosition p = cursorPixel(w, x, y);
    e.x = p.x;
    e.y = p.y;
    self(w)->events_.push_back(e);
  });
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
    if (imguiWantsMouse()) return;
    InputEvent e{InputEvent::Type::Scroll};
    e.y = dy;
    self(w)->events_.push_back(e);
  });
}

ViewerWindow::~ViewerWindow() {
  if (window_) glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> ViewerWindow::requiredInstanceExtensions() {
  uint32_t n = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&n);
  if (!names) throw std::runtime_error("window surfaces unsupported: " + gLastGlfwError);
  return {names, names + n};
}

VkSurfaceKHR ViewerWindow::createSurface(VkInstance instance) {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  const VkResult r = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
  if (r != VK_SUCCESS)
    throw std::runtime_error("window surfaces unsupported: cannot create a Vulkan surface for the window (" +
                             gLastGlfwError + ", VkResult " + std::to_string(int(r)) + ")");
  return surface;
}

std::vector<InputEvent> ViewerWindow::poll() {
  glfwPollEvents();
  std::vector<InputEvent> events;
  events.swap(events_);
  return events;
}

bool ViewerWindow::closeRequested() const { return glfwWindowShouldClose(window_); }

VkExtent2D ViewerWindow::framebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {uint32_t(w), uint32_t(h)};
}

bool ViewerWindow::minimized() const {
  const auto size = framebufferSize();
  return glfwGetWindowAttrib(window_, GLFW_ICONIFIED) || size.width == 0 || size.height == 0;
}

void ViewerWindow::setIconified(bool iconified) {
  if (iconified)
    glfwIconifyWindow(window_);
  else
    glfwRestoreWindow(window_);
}

void ViewerWindow::setSize(uint32_t width, uint32_t height) { glfwSetWindowSize(window_, int(width), int(height)); }

}  // namespace sg::app::view
