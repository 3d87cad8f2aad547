#include "view_script.hpp"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "../option_checks.hpp"

namespace sg::app::view {
namespace {

struct LineError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The whole token as a number, else a LineError naming what it should be.
double number(const std::string& token, const char* what) {
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(token, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != token.size() || !std::isfinite(value)) throw LineError(std::string(what) + " '" + token + "' is not a number");
  return value;
}

int count(const std::string& token, const char* what, int min) {
  const double v = number(token, what);
  if (v != double(int(v)) || v < min || v > 1e7)
    throw LineError(std::string(what) + " '" + token + "' must be a whole number from " + std::to_string(min));
  return int(v);
}

int mouseButton(const std::string& name) {
  if (name == "left") return GLFW_MOUSE_BUTTON_LEFT;
  if (name == "right") return GLFW_MOUSE_BUTTON_RIGHT;
  if (name == "middle") return GLFW_MOUSE_BUTTON_MIDDLE;
  throw LineError("mouse button '" + name + "' (expected left, right or middle)");
}

void arity(const std::vector<std::string>& t, size_t min, size_t max, const char* usage) {
  if (t.size() < min || t.size() > max) throw LineError(std::string("expected: ") + usage);
}

ScriptStep parseLine(const std::vector<std::string>& t) {
  ScriptStep s;
  const std::string& event = t[0];
  if (event == "key") {
    arity(t, 2, 3, "key NAME [FRAMES]");
    s.kind = ScriptStep::Kind::Key;
    s.key = keyCode(t[1]);
    if (!s.key) throw LineError("unknown key '" + t[1] + "'");
    if (t.size() == 3) s.frames = count(t[2], "frames", 1);
  } else if (event == "mouse") {
    if (t.size() < 2) throw LineError("expected: mouse move|drag|click ...");
    if (t[1] == "move") {
      arity(t, 4, 4, "mouse move X Y");
      s.kind = ScriptStep::Kind::MouseMove;
    } else if (t[1] == "drag") {
      arity(t, 6, 7, "mouse drag X0 Y0 X1 Y1 [left|right|middle]");
      s.kind = ScriptStep::Kind::MouseDrag;
      s.x1 = number(t[4], "x");
      s.y1 = number(t[5], "y");
      if (t.size() == 7) s.button = mouseButton(t[6]);
    } else if (t[1] == "click") {
      arity(t, 4, 5, "mouse click X Y [left|right|middle]");
      s.kind = ScriptStep::Kind::MouseClick;
      if (t.size() == 5) s.button = mouseButton(t[4]);
    } else {
      throw LineError("unknown mouse event '" + t[1] + "' (expected move, drag or click)");
    }
    s.x0 = number(t[2], "x");
    s.y0 = number(t[3], "y");
  } else if (event == "scroll") {
    arity(t, 2, 2, "scroll STEPS");
    s.kind = ScriptStep::Kind::Scroll;
    s.y0 = number(t[1], "steps");
  } else if (event == "wait") {
    arity(t, 2, 2, "wait FRAMES");
    s.kind = ScriptStep::Kind::Wait;
    s.frames = count(t[1], "frames", 0);
  } else if (event == "screenshot" || event == "window-screenshot") {
    arity(t, 2, 2, "screenshot PATH");
    s.kind = event == "screenshot" ? ScriptStep::Kind::Screenshot : ScriptStep::Kind::WindowScreenshot;
    s.path = t[1];
  } else if (event == "resize") {
    arity(t, 3, 3, "resize WIDTH HEIGHT");
    s.kind = ScriptStep::Kind::Resize;
    s.width = uint32_t(count(t[1], "width", 1));
    s.height = uint32_t(count(t[2], "height", 1));
    if (s.width > kMaxOutputSide || s.height > kMaxOutputSide)
      throw LineError("resize: each side at most " + std::to_string(kMaxOutputSide));
  } else if (event == "effect") {
    arity(t, 3, 3, "effect NAME on|off");
    if (t[2] != "on" && t[2] != "off") throw LineError("effect " + t[1] + ": expected on or off, not '" + t[2] + "'");
    s.kind = ScriptStep::Kind::Effect;
    s.path = t[1];
    s.frames = t[2] == "on" ? 1 : 0;
  } else if (event == "minimize" || event == "restore") {
    arity(t, 1, 1, event == "minimize" ? "minimize" : "restore");
    s.kind = event == "minimize" ? ScriptStep::Kind::Minimize : ScriptStep::Kind::Restore;
  } else if (event == "quit") {
    arity(t, 1, 1, "quit");
    s.kind = ScriptStep::Kind::Quit;
  } else {
    throw LineError("unknown event '" + event +
                    "' (expected key, mouse, scroll, wait, screenshot, window-screenshot, resize, effect, minimize, "
                    "restore or quit)");
  }
  return s;
}

}  // namespace

int keyCode(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  if (n.size() == 1 && n[0] >= 'A' && n[0] <= 'Z') return GLFW_KEY_A + (n[0] - 'A');
  if (n.size() == 1 && n[0] >= '0' && n[0] <= '9') return GLFW_KEY_0 + (n[0] - '0');
  if (n.size() >= 2 && n[0] == 'F' && std::all_of(n.begin() + 1, n.end(), ::isdigit)) {
    const int f = std::stoi(n.substr(1));
    if (f >= 1 && f <= 12) return GLFW_KEY_F1 + f - 1;
  }
  static const std::map<std::string, int> named{{"SPACE", GLFW_KEY_SPACE},       {"ESCAPE", GLFW_KEY_ESCAPE},
                                                {"TAB", GLFW_KEY_TAB},           {"ENTER", GLFW_KEY_ENTER},
                                                {"LEFT_SHIFT", GLFW_KEY_LEFT_SHIFT}, {"LEFT", GLFW_KEY_LEFT},
                                                {"RIGHT", GLFW_KEY_RIGHT},       {"UP", GLFW_KEY_UP},
                                                {"DOWN", GLFW_KEY_DOWN}};
  const auto it = named.find(n);
  return it == named.end() ? 0 : it->second;
}

std::vector<ScriptStep> loadScript(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("--script " + file.string() + ": cannot read it");
  std::vector<ScriptStep> steps;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (const auto hash = text.find('#'); hash != std::string::npos) text.erase(hash);
    std::istringstream words(text);
    std::vector<std::string> tokens;
    for (std::string w; words >> w;) tokens.push_back(w);
    if (tokens.empty()) continue;
    try {
      steps.push_back(parseLine(tokens));
    } catch (const LineError& e) {
      throw std::runtime_error(file.string() + ":" + std::to_string(line) + ": " + e.what());
    }
    steps.back().line = line;
  }
  return steps;
}

}  // namespace sg::app::view
