#pragma once
// One input event, from the window or a script: the viewer handles both alike.
namespace sg::app::view {

struct InputEvent {
  enum class Type { KeyDown, KeyUp, MouseMove, ButtonDown, ButtonUp, Scroll };
  Type type = Type::MouseMove;
  int key = 0;     // GLFW key code (KeyDown, KeyUp)
  int button = 0;  // GLFW mouse button (ButtonDown, ButtonUp)
  double x = 0.0, y = 0.0;  // cursor in framebuffer pixels (the frame's); Scroll: y is the wheel's steps
};

// The window system gives the cursor in screen coordinates, which on a HiDPI
// display (or with desktop scaling) are not the framebuffer's pixels that the
// frame, and a pick, are in.
struct CursorPosition {
  double x = 0.0, y = 0.0;
};
inline CursorPosition framebufferPixel(double x, double y, int windowWidth, int windowHeight, int framebufferWidth,
                                       int framebufferHeight) {
  if (windowWidth <= 0 || windowHeight <= 0) return {x, y};  // minimized: nothing to scale by
  return {x * double(framebufferWidth) / double(windowWidth), y * double(framebufferHeight) / double(windowHeight)};
}

}  // namespace sg::app::view
