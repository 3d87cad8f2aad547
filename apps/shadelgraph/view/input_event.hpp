#pragma once
// One input event, from the window or a script: the viewer handles both alike.
namespace sg::app::view {

struct InputEvent {
  enum class Type { KeyDown, KeyUp, MouseMove, ButtonDown, ButtonUp, Scroll };
  Type type = Type::MouseMove;
  int key = 0;     // GLFW key code (KeyDown, KeyUp)
  int button = 0;  // GLFW mouse button (ButtonDown, ButtonUp)
  double x = 0.0, y = 0.0;  // cursor in window pixels; Scroll: y is the wheel's steps
};

}  // namespace sg::app::view
