#pragma once
// `shadelgraph view`: the scene in a window, rendered each frame through the
// same AppSession and frame as `render`, shown through a swapchain with Dear
// ImGui panels over it; driven by the window's input or a --script.
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <shadelgraph/gpu/swapchain.hpp>

#include "../animation_player.hpp"
#include "../app_session.hpp"
#include "../command_options.hpp"
#include "camera_controller.hpp"
#include "frame_presenter.hpp"
#include "input_event.hpp"
#include "timing_history.hpp"
#include "view_script.hpp"
#include "viewer_window.hpp"

namespace sg::app::view {

class Viewer {
 public:
  explicit Viewer(const ViewArgs& args);
  ~Viewer();
  // Shows frames until the window closes, the script ends or quits, or Escape.
  void run();
  // Takes the window's Vulkan objects down (so validation has seen all there is to see).
  void close();
  int validationExitCode() const { return session_->validationExitCode(); }

  // What the panels (viewer_panels.cpp) show and change.
  AppSession& session() { return *session_; }
  const render::FrameResult& lastFrame() const { return frame_; }
  const plugins::DecoupledStats& stats() const { return stats_; }
  const TimingHistory& history() const { return history_; }
  plugins::DecoupledSettings& decoupledSettings() { return decoupled_; }
  void rebuildRenderer() { rebuild_ = true; }  // the settings above changed: at the next frame
  void setGlobalMode(int mode);                 // 0: each object's own, 1 forward, 2 decoupled, 3 auto
  int globalMode() const { return globalMode_; }
  void setObjectMode(uint32_t instance, scene::ShadingMode mode);
  void setObjectMaterial(uint32_t instance, const std::string& material);
  const std::string& objectMaterial(uint32_t instance) const { return materials_[instance]; }
  // The views keys 1-6 choose: render's --view ones, then every object in a debug material.
  static const std::vector<std::string>& viewNames();
  int viewIndex() const;
  void setView(int index);
  // The frame's effect passes (shadows, environment, bloom): each can be left out of the frame.
  std::vector<std::string> effects() const;
  bool effectOn(const std::string& effect) const { return !disabledEffects_.count(effect); }
  void setEffect(const std::string& effect, bool on);
  std::optional<uint32_t> selected;
  // kRenderCamera: the one render would use; kFreeCamera; 0..cameras-1: the scene's; then the camera paths.
  static constexpr int kRenderCamera = -2, kFreeCamera = -1;
  int cameraChoice() const { return cameraChoice_; }
  void chooseCamera(int choice);
  std::vector<std::string> cameraNames() const;
  bool paused = false;
  void saveFrame(const std::filesystem::path& path) const;
  void requestWindowScreenshot(const std::filesystem::path& path) { windowShot_ = path; }
  std::filesystem::path nextScreenshotPath();

 private:
  void handle(const InputEvent& event);
  // Runs script steps until one needs frames; false when the script has ended.
  void stepScript();
  void applySize();
  void renderFrame();
  scene::Camera currentCamera() const;
  void freeCameraFromCurrent();
  void pick(double x, double y);
  void finishPick(glm::uvec2 pixel);

  ViewArgs args_;
  std::unique_ptr<ViewerWindow> window_;
  std::unique_ptr<AppSession> session_;
  std::unique_ptr<gpu::Swapchain> swapchain_;
  std::unique_ptr<FramePresenter> presenter_;
  std::optional<AnimationPlayer> animations_;
  render::RenderSettings settings_;
  plugins::DecoupledSettings decoupled_;
  bool rebuild_ = false;
  int globalMode_ = 0;
  std::vector<scene::ShadingMode> modes_;  // requested per object
  std::vector<std::string> materials_;     // per object, as the scene has it or chosen
  std::string materialView_;               // a debug material every object shows instead (views 5, 6); empty: none
  plugin::ResolvedFrame fullFrame_;        // the frame with every effect
  std::set<std::string> disabledEffects_;
  CameraController controller_;
  int cameraChoice_ = -1;
  std::optional<scene::Camera> fixedCamera_;  // --frame's pose
  render::FrameResult frame_;
  plugins::DecoupledStats stats_;
  TimingHistory history_;
  std::optional<glm::uvec2> pendingPick_;  // a click's pixel, for the next frame's object-pick pass
  uint64_t shown_ = 0;   // frames shown
  uint64_t played_ = 0;  // frames of scene time (not while paused)
  std::optional<uint64_t> minimizedSince_;  // while minimized: the idle waits so far
  bool panels_ = true;
  bool quit_ = false;
  // Input state.
  std::set<int> keysHeld_;
  int buttonHeld_ = -1;
  double cursorX_ = 0, cursorY_ = 0, dragPixels_ = 0;
  // Script state.
  std::vector<ScriptStep> script_;
  size_t scriptNext_ = 0;
  int scriptWait_ = 0;
  std::optional<int> scriptKeyUp_;  // released when scriptWait_ runs out
  std::optional<std::filesystem::path> frameShot_, windowShot_;
  int screenshots_ = 0;
};

void drawPanels(Viewer& viewer);

}  // namespace sg::app::view
