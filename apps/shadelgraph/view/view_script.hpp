#pragma once
// `view --script FILE`: input events replayed one a line, so the viewer runs
// (and is tested) without a person. Blank lines and # comments are skipped.
//   key NAME [FRAMES]              press a key, hold it FRAMES frames (default 1)
//   mouse move X Y                 move the cursor (window pixels)
//   mouse drag X0 Y0 X1 Y1 [BUTTON]  press at X0 Y0, move to X1 Y1, release (left, right, middle)
//   mouse click X Y [BUTTON]       press and release without moving (left: pick)
//   scroll STEPS                   the mouse wheel (zoom)
//   wait N                         show N frames (minimized: N idle waits of 0.1 s)
//   screenshot PATH                the frame as render writes it (PNG)
//   window-screenshot PATH         the whole window with its panels (PNG)
//   resize W H                     the window to W x H
//   effect NAME on|off             an effect pass (shadows, environment, bloom) in or out of the frame
//   minimize, restore              iconify the window (needs a window manager) and bring it back
//   quit
// An unknown event or a bad argument fails naming the file and the line.
#include <filesystem>
#include <string>
#include <vector>

namespace sg::app::view {

struct ScriptStep {
  enum class Kind { Key, MouseMove, MouseDrag, MouseClick, Scroll, Wait, Screenshot, WindowScreenshot, Resize, Effect, Minimize, Restore, Quit };
  Kind kind = Kind::Wait;
  int key = 0;     // GLFW key code
  int button = 0;  // GLFW mouse button
  int frames = 1;  // Key: frames held; Wait: frames shown
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // Mouse*: positions; Scroll: y0 steps
  uint32_t width = 0, height = 0;          // Resize
  std::string path;                        // Screenshot; Effect: its name (frames: 1 on, 0 off)
  int line = 0;
};

// Throws "FILE:LINE: ..." for the first line that is not an event.
std::vector<ScriptStep> loadScript(const std::filesystem::path& file);
// GLFW key code of a name (A-Z, 0-9, F1-F12, SPACE, ESCAPE, TAB, ENTER, LEFT_SHIFT...); 0 when unknown.
int keyCode(const std::string& name);

}  // namespace sg::app::view
