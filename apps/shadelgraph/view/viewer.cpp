#include "viewer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <GLFW/glfw3.h>

#include <shadelgraph/image/png.hpp>

#include "../frame_setup.hpp"
#include "../output_file.hpp"

namespace sg::app::view {
namespace {

constexpr float kSecondsPerFrame = 1.0f / 30.0f;  // scene time a frame, as render's --frames steps
constexpr double kClickPixels = 3.0;              // a press and release closer than this is a click, not a drag
// Passes that add only what the scene calls for, so a frame without them still renders (docs/composing-frames.md).
const char* const kEffectPasses[] = {"shadows", "environment", "bloom"};
// Views after render's --view ones: every object in a debug material.
const std::pair<const char*, const char*> kMaterialViews[] = {{"uv checker", "debug-uv-checker"},
                                                              {"triangle id", "debug-triangle-id"}};

gpu::ContextOptions windowContextOptions() {
  auto options = gpu::ContextOptions::fromEnvironment();
  options.instanceExtensions = ViewerWindow::requiredInstanceExtensions();
  options.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  return options;
}

void writeImage(const std::filesystem::path& path, const gpu::HostImage& image) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  image::writePng(path.string(), image.width, image.height, image.rgba8.data());
}

}  // namespace

Viewer::Viewer(const ViewArgs& args) : args_(args) {
  checkViewArgs(args_);
  if (!args_.script.empty()) script_ = loadScript(args_.script);  // a bad script fails before a window opens
  const RenderArgs& r = args_.frame;
  settings_ = renderSettings(r);
  decoupled_ = app::decoupledSettings(r);
  window_ = std::make_unique<ViewerWindow>("shadelgraph view", settings_.width, settings_.height);
  session_ = std::make_unique<AppSession>(r.scene, r.mode, decoupled_, r.materials, r.frameGraph, windowContextOptions());
  if (r.camera) checkCameraIndex(*session_, *r.camera);
  if (r.frame) fixedCamera_ = pathCamera(*session_, r.path, *r.frame);
  animations_.emplace(session_->scene, r.animation);
  for (const auto& instance : session_->scene.instances) {
    modes_.push_back(instance.shading);
    materials_.push_back(instance.material.empty() ? "gltf-pbr" : instance.material);
  }
  swapchain_ = std::make_unique<gpu::Swapchain>(session_->device->context(),
                                                window_->createSurface(session_->context->instance()),
                                                window_->framebufferSize());
  presenter_ = std::make_unique<FramePresenter>(*session_->context, session_->device->memory(), *swapchain_,
                                                window_->handle());
  fullFrame_ = session_->renderer->frame();
  panels_ = !args_.hidePanels;
  // The camera render would use (kRenderCamera), until the user moves it or chooses another.
  cameraChoice_ = r.camera ? *r.camera : kRenderCamera;
  freeCameraFromCurrent();
  cameraChoice_ = r.camera ? *r.camera : kRenderCamera;
}

void Viewer::close() {
  presenter_.reset();
  if (session_ && session_->renderer) session_->renderer->finishFrames();
  swapchain_.reset();
}

Viewer::~Viewer() {
  presenter_.reset();
  if (session_ && session_->renderer) session_->renderer->finishFrames();
  swapchain_.reset();
  session_.reset();
  window_.reset();
}

std::vector<std::string> Viewer::cameraNames() const {
  std::vector<std::string> names;
  for (size_t i = 0; i < session_->scene.cameras.size(); ++i)
    names.push_back("camera " + std::to_string(i) + ": " + session_->scene.cameras[i].name);
  for (size_t i = 0; i < session_->cameraPaths.size(); ++i)
    names.push_back("path " + std::to_string(i) + ": " + session_->cameraPaths[i].name);
  return names;
}

scene::Camera Viewer::currentCamera() const {
  if (cameraChoice_ == kRenderCamera) {
    if (fixedCamera_) return *fixedCamera_;
    render::RenderSettings asRender = settings_;
    asRender.cameraOverride.reset();
    return session_->renderer->camera(asRender);
  }
  const int cameras = int(session_->scene.cameras.size());
  if (cameraChoice_ >= 0 && cameraChoice_ < cameras) return session_->scene.cameras[size_t(cameraChoice_)];
  if (cameraChoice_ >= cameras) {
    const auto pose = scene::evaluatePose(session_->cameraPaths[size_t(cameraChoice_ - cameras)], float(played_) * kSecondsPerFrame);
    return scene::poseCamera(pose, scene::worldBounds(session_->scene));
  }
  return controller_.camera();
}

void Viewer::chooseCamera(int choice) {
  const int count = int(session_->scene.cameras.size() + session_->cameraPaths.size());
  if (choice >= count) {
    freeCameraFromCurrent();
    choice = kFreeCamera;
  }
  cameraChoice_ = choice;
  std::printf("camera: %s\n", cameraChoice_ < 0 ? "free" : cameraNames()[size_t(cameraChoice_)].c_str());
}

// Moving the camera by hand leaves the scene's camera (or path) where it is, as the free camera.
void Viewer::freeCameraFromCurrent() {
  if (cameraChoice_ == kFreeCamera) return;
  const scene::Camera c = currentCamera();
  controller_.reset(c, glm::length(scene::worldBounds(session_->scene).center() - c.position()));
  cameraChoice_ = kFreeCamera;
}

void Viewer::setGlobalMode(int mode) {
  globalMode_ = mode;
  static const scene::ShadingMode modes[] = {scene::ShadingMode::Auto, scene::ShadingMode::Forward,
                                             scene::ShadingMode::Decoupled, scene::ShadingMode::Auto};
  for (uint32_t i = 0; i < modes_.size(); ++i)
    setObjectMode(i, mode == 0 ? session_->scene.instances[i].shading : modes[mode]);
}

void Viewer::setObjectMode(uint32_t instance, scene::ShadingMode mode) {
  modes_[instance] = mode;
  session_->renderer->setObjectMode(instance, mode);
}

void Viewer::setObjectMaterial(uint32_t instance, const std::string& material) {
  materials_[instance] = material;
  if (materialView_.empty()) session_->renderer->setObjectMaterial(instance, material);
}

const std::vector<std::string>& Viewer::viewNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& view : debugViews()) n.push_back(view.first);
    for (const auto& view : kMaterialViews) n.push_back(view.first);
    return n;
  }();
  return names;
}

int Viewer::viewIndex() const {
  for (size_t i = 0; i < std::size(kMaterialViews); ++i)
    if (materialView_ == kMaterialViews[i].second) return int(debugViews().size() + i);
  for (size_t i = 0; i < debugViews().size(); ++i)
    if (debugViews()[i].second == decoupled_.view) return int(i);
  return 0;
}

void Viewer::setView(int index) {
  const size_t decoupledViews = debugViews().size();
  const auto view = size_t(index) < decoupledViews ? debugViews()[size_t(index)].second : plugins::DebugView::Final;
  if (view != decoupled_.view) {
    decoupled_.view = view;
    rebuild_ = true;
  }
  materialView_ = size_t(index) < decoupledViews ? "" : kMaterialViews[size_t(index) - decoupledViews].second;
  for (uint32_t i = 0; i < materials_.size(); ++i)
    session_->renderer->setObjectMaterial(i, materialView_.empty() ? materials_[i] : materialView_);
  std::printf("view: %s\n", viewNames()[size_t(index)].c_str());
}

std::vector<std::string> Viewer::effects() const {
  std::vector<std::string> found;
  for (const char* effect : kEffectPasses)
    for (const auto& pass : fullFrame_.passes)
      if (pass.pass->name == effect) found.push_back(effect);
  return found;
}

void Viewer::setEffect(const std::string& effect, bool on) {
  const auto have = effects();
  if (std::find(have.begin(), have.end(), effect) == have.end()) {
    std::string list;
    for (const auto& e : have) list += (list.empty() ? "" : ", ") + e;
    throw std::invalid_argument("effect '" + effect + "': the frame has no such effect (it has: " +
                                (list.empty() ? "none" : list) + ")");
  }
  if (on)
    disabledEffects_.erase(effect);
  else
    disabledEffects_.insert(effect);
  plugin::ResolvedFrame frame = fullFrame_;
  std::erase_if(frame.passes, [&](const plugin::ResolvedPass& p) { return disabledEffects_.count(p.pass->name) != 0; });
  session_->renderer->setFrame(std::move(frame));
  std::printf("effect %s: %s\n", effect.c_str(), on ? "on" : "off");
}

std::filesystem::path Viewer::nextScreenshotPath() {
  char name[32];
  std::snprintf(name, sizeof name, "screenshot-%03d.png", screenshots_++);
  return std::filesystem::path(args_.screenshotDir) / name;
}

void Viewer::saveFrame(const std::filesystem::path& path) const {
  writeImage(path, frame_.image);
  std::printf("wrote %s (%ux%u, %u objects decoupled)\n", path.string().c_str(), frame_.image.width, frame_.image.height,
              stats_.objects);
}

// A click asks the next frame for the object under the pixel: that frame holds the object-pick pass.
void Viewer::pick(double x, double y) {
  if (x < 0 || y < 0 || x >= double(settings_.width) || y >= double(settings_.height)) {
    std::printf("pick %.0f %.0f: outside the frame\n", x, y);
    return;
  }
  pendingPick_ = glm::uvec2(uint32_t(x), uint32_t(y));
}

// The pick frame's answer: the object under the pixel switches between decoupled and forward.
void Viewer::finishPick(glm::uvec2 pixel) {
  if (!frame_.pickAnswered) {
    std::printf("pick %u %u: the frame has no object-pick pass\n", pixel.x, pixel.y);
    return;
  }
  selected = frame_.picked;
  if (!frame_.picked) {
    std::printf("pick %u %u: nothing\n", pixel.x, pixel.y);
    return;
  }
  const uint32_t hit = *frame_.picked;
  // Auto counts as decoupled: what it asks for.
  const auto mode = modes_[hit] == scene::ShadingMode::Forward ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward;
  setObjectMode(hit, mode);
  std::printf("pick %u %u: '%s' -> %s\n", pixel.x, pixel.y, session_->scene.instances[hit].name.c_str(),
              std::string(scene::toString(mode)).c_str());
}

void Viewer::handle(const InputEvent& e) {
  using T = InputEvent::Type;
  switch (e.type) {
    case T::KeyDown:
      keysHeld_.insert(e.key);
      if (e.key == GLFW_KEY_ESCAPE) quit_ = true;
      if (e.key == GLFW_KEY_F) {
        controller_.frame(scene::worldBounds(session_->scene), float(settings_.width) / float(settings_.height));
        cameraChoice_ = kFreeCamera;
        std::printf("camera: free, framing the scene\n");
      }
      if (e.key == GLFW_KEY_P) frameShot_ = nextScreenshotPath();
      if (e.key == GLFW_KEY_H) panels_ = !panels_;
      if (e.key == GLFW_KEY_V) {
        freeCameraFromCurrent();
        controller_.flyMode = !controller_.flyMode;
        std::printf("camera: %s\n", controller_.flyMode ? "fly" : "orbit");
      }
      if (e.key == GLFW_KEY_C) chooseCamera(std::max(cameraChoice_ + 1, 0));
      if (e.key == GLFW_KEY_SPACE) paused = !paused;
      if (e.key >= GLFW_KEY_1 && e.key < GLFW_KEY_1 + int(viewNames().size())) setView(e.key - GLFW_KEY_1);
      break;
    case T::KeyUp:
      keysHeld_.erase(e.key);
      break;
    case T::ButtonDown:
      buttonHeld_ = e.button;
      cursorX_ = e.x;
      cursorY_ = e.y;
      dragPixels_ = 0;
      break;
    case T::ButtonUp:
      if (e.button == GLFW_MOUSE_BUTTON_LEFT && buttonHeld_ == e.button && dragPixels_ < kClickPixels) pick(e.x, e.y);
      buttonHeld_ = -1;
      break;
    case T::MouseMove: {
      const double dx = e.x - cursorX_, dy = e.y - cursorY_;
      cursorX_ = e.x;
      cursorY_ = e.y;
      if (buttonHeld_ < 0) break;
      dragPixels_ += std::hypot(dx, dy);
      if (dragPixels_ < kClickPixels) break;
      freeCameraFromCurrent();
      if (buttonHeld_ == GLFW_MOUSE_BUTTON_LEFT && controller_.flyMode)
        controller_.look(float(dx), float(dy));
      else if (buttonHeld_ == GLFW_MOUSE_BUTTON_LEFT)
        controller_.orbit(float(dx), float(dy));
      else
        controller_.pan(float(dx), float(dy), float(settings_.height));
      break;
    }
    case T::Scroll:
      freeCameraFromCurrent();
      controller_.zoom(float(e.y));
      break;
  }
}

void Viewer::stepScript() {
  if (scriptWait_ > 0) {
    --scriptWait_;
    if (scriptWait_ == 0 && scriptKeyUp_) {
      handle({InputEvent::Type::KeyUp, *scriptKeyUp_});
      scriptKeyUp_.reset();
    }
    if (scriptWait_ > 0 || scriptKeyUp_) return;
  }
  if (script_.empty()) return;
  using K = ScriptStep::Kind;
  while (scriptWait_ == 0 && !frameShot_ && !windowShot_ && !quit_) {
    if (scriptNext_ == script_.size()) {
      quit_ = true;  // a script's end ends the viewer
      return;
    }
    const ScriptStep& s = script_[scriptNext_++];
    switch (s.kind) {
      case K::Key:
        handle({InputEvent::Type::KeyDown, s.key});
        scriptKeyUp_ = s.key;
        scriptWait_ = s.frames;
        break;
      case K::MouseMove:
        handle({InputEvent::Type::MouseMove, 0, 0, s.x0, s.y0});
        break;
      case K::MouseDrag: {
        handle({InputEvent::Type::MouseMove, 0, 0, s.x0, s.y0});
        handle({InputEvent::Type::ButtonDown, 0, s.button, s.x0, s.y0});
        constexpr int kSteps = 8;
        for (int i = 1; i <= kSteps; ++i)
          handle({InputEvent::Type::MouseMove, 0, 0, s.x0 + (s.x1 - s.x0) * i / kSteps, s.y0 + (s.y1 - s.y0) * i / kSteps});
        handle({InputEvent::Type::ButtonUp, 0, s.button, s.x1, s.y1});
        break;
      }
      case K::MouseClick:
        handle({InputEvent::Type::MouseMove, 0, 0, s.x0, s.y0});
        handle({InputEvent::Type::ButtonDown, 0, s.button, s.x0, s.y0});
        handle({InputEvent::Type::ButtonUp, 0, s.button, s.x0, s.y0});
        break;
      case K::Scroll:
        handle({InputEvent::Type::Scroll, 0, 0, 0, s.y0});
        break;
      case K::Wait:
        scriptWait_ = s.frames;
        break;
      case K::Screenshot:
        frameShot_ = s.path;
        break;
      case K::WindowScreenshot:
        windowShot_ = s.path;
        break;
      case K::Resize: {
        window_->setSize(s.width, s.height);
        // The window system answers asynchronously: wait (a little) for the new size.
        for (int i = 0; i < 200; ++i) {
          const auto size = window_->framebufferSize();
          if (size.width == s.width && size.height == s.height) break;
          glfwWaitEventsTimeout(0.01);
        }
        const auto size = window_->framebufferSize();
        if (size.width != s.width || size.height != s.height)
          throw std::runtime_error(args_.script + ":" + std::to_string(s.line) + ": resize " + std::to_string(s.width) +
                                   " " + std::to_string(s.height) + ": the window system kept " +
                                   std::to_string(size.width) + "x" + std::to_string(size.height));
        break;
      }
      case K::Minimize:
      case K::Restore: {
        const bool iconify = s.kind == K::Minimize;
        window_->setIconified(iconify);
        for (int i = 0; i < 200 && window_->minimized() != iconify; ++i) glfwWaitEventsTimeout(0.01);
        if (window_->minimized() != iconify)
          throw std::runtime_error(args_.script + ":" + std::to_string(s.line) + ": " +
                                   (iconify ? "minimize: the window system did not iconify the window (is a window "
                                              "manager running?)"
                                            : "restore: the window system kept the window iconified"));
        break;
      }
      case K::Effect:
        try {
          setEffect(s.path, s.frames != 0);
        } catch (const std::invalid_argument& e) {
          throw std::runtime_error(args_.script + ":" + std::to_string(s.line) + ": " + e.what());
        }
        break;
      case K::Quit:
        quit_ = true;
        break;
    }
  }
}

// The frame follows the window's framebuffer: only what depends on the size is made again.
void Viewer::applySize() {
  const VkExtent2D size = window_->framebufferSize();
  if (size.width == 0 || size.height == 0) return;
  if (size.width != settings_.width || size.height != settings_.height) {
    settings_.width = size.width;
    settings_.height = size.height;
    std::printf("size: %ux%u\n", size.width, size.height);
  }
  swapchain_->resize(size);
}

void Viewer::renderFrame() {
  if (rebuild_) {
    rebuild_ = false;
    session_->rebuildRenderer(decoupled_);
    for (uint32_t i = 0; i < modes_.size(); ++i) {
      session_->renderer->setObjectMode(i, modes_[i]);
      session_->renderer->setObjectMaterial(i, materialView_.empty() ? materials_[i] : materialView_);
    }
  }
  // As render: its own choice of camera (the scene's first, else framing at this aspect), or the one chosen here.
  if (cameraChoice_ == kRenderCamera && !fixedCamera_)
    settings_.cameraOverride.reset();
  else
    settings_.cameraOverride = currentCamera();
  settings_.time = float(played_) * kSecondsPerFrame;
  if (animations_->playing()) animations_->poseAt(float(args_.frame.time) + float(played_) * kSecondsPerFrame, *session_->renderer);
  settings_.readback = true;
  settings_.keepPlan = panels_;
  settings_.pick = pendingPick_;
  pendingPick_.reset();
  frame_ = session_->renderer->render(settings_);
  if (settings_.pick) finishPick(*settings_.pick);
  settings_.pick.reset();
  session_->decoupled->observeTimings(frame_.timings);
  stats_ = session_->decoupled->stats();
  history_.add(frame_.timings);
}

void Viewer::run() {
  while (!quit_) {
    for (const auto& e : window_->poll()) handle(e);
    if (window_->closeRequested()) break;
    stepScript();
    if (quit_) break;
    // Fly: held keys move the camera a frame's worth.
    const auto held = [&](int key) { return keysHeld_.count(key) ? 1.0f : 0.0f; };
    const float forward = held(GLFW_KEY_W) - held(GLFW_KEY_S), right = held(GLFW_KEY_D) - held(GLFW_KEY_A),
                up = held(GLFW_KEY_E) - held(GLFW_KEY_Q);
    if (forward != 0.0f || right != 0.0f || up != 0.0f) {
      freeCameraFromCurrent();
      controller_.fly(forward, right, up, kSecondsPerFrame);
    }
    if (window_->minimized()) {
      if (!minimizedSince_) {
        minimizedSince_ = 0;
        std::printf("minimized after %llu frames\n", (unsigned long long)shown_);
      }
      ++*minimizedSince_;
      glfwWaitEventsTimeout(0.1);  // nothing is rendered, the swapchain left alone, until the window comes back
      continue;
    }
    if (minimizedSince_) {
      std::printf("restored after %llu frames (%llu idle waits)\n", (unsigned long long)shown_,
                  (unsigned long long)*minimizedSince_);
      minimizedSince_.reset();
    }
    applySize();
    renderFrame();
    presenter_->beginUi();
    if (panels_) drawPanels(*this);
    gpu::HostImage windowPixels;
    const bool shown = presenter_->present(frame_.image, panels_, windowShot_ ? &windowPixels : nullptr);
    if (frameShot_) saveFrame(*frameShot_);
    if (windowShot_ && shown) {
      writeImage(*windowShot_, windowPixels);
      std::printf("wrote %s (%ux%u, the window)\n", windowShot_->string().c_str(), windowPixels.width, windowPixels.height);
    }
    frameShot_.reset();
    windowShot_.reset();
    if (!args_.record.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "frame-%06llu.png", (unsigned long long)shown_);
      writeImage(std::filesystem::path(args_.record) / name, frame_.image);
    }
    ++shown_;
    if (!paused) ++played_;
  }
  session_->renderer->finishFrames();
  std::printf("viewer: %llu frames shown\n", (unsigned long long)shown_);
}

}  // namespace sg::app::view
