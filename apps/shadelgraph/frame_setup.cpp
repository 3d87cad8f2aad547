#include "frame_setup.hpp"

#include <stdexcept>

#include "option_checks.hpp"

namespace sg::app {

const std::vector<std::pair<std::string, plugins::DebugView>>& debugViews() {
  static const std::vector<std::pair<std::string, plugins::DebugView>> views{{"final", plugins::DebugView::Final},
                                                                             {"level", plugins::DebugView::Level},
                                                                             {"occupancy", plugins::DebugView::Occupancy},
                                                                             {"sheet", plugins::DebugView::Sheet}};
  return views;
}

plugins::DecoupledSettings decoupledSettings(const RenderArgs& args) {
  plugins::DecoupledSettings decoupled{.storageFactor = args.storage, .filter = args.filter,
                                      .shadeRate = uint32_t(args.shadeRate), .overlap = args.framesInFlight > 1,
                                      .shadeBudgetMs = args.shadeBudget};
  decoupled.markRequests = args.mark == "depth-pass";
  for (const auto& [name, view] : debugViews())
    if (name == args.view) decoupled.view = view;
  if (args.bias) decoupled.fixedBias = float(args.bias.value());
  return decoupled;
}

render::RenderSettings renderSettings(const RenderArgs& args) {
  render::RenderSettings settings;
  parseSize("--size", args.size, settings.width, settings.height);
  if (args.camera) settings.camera = *args.camera;
  settings.aliasing = !args.noAliasing;
  settings.framesInFlight = uint32_t(args.framesInFlight);
  settings.zPrepass = args.zPrepass == "on"    ? render::ZPrepass::On
                      : args.zPrepass == "off" ? render::ZPrepass::Off
                                               : render::ZPrepass::Auto;
  return settings;
}

scene::Camera pathCamera(const AppSession& session, int path, int frame) {
  if (session.cameraPaths.empty()) throw std::invalid_argument("--frame: the scene has no camera paths (a .json scene file defines them)");
  if (path < 0 || size_t(path) >= session.cameraPaths.size())
    throw std::invalid_argument("--path " + std::to_string(path) + ": the scene has " +
                                std::to_string(session.cameraPaths.size()) + " camera path(s)");
  const auto pose = scene::evaluatePose(session.cameraPaths[size_t(path)], float(frame) / 30.0f);
  return scene::poseCamera(pose, scene::worldBounds(session.scene));
}

void checkCameraIndex(const AppSession& session, int index) {
  if (size_t(index) >= session.scene.cameras.size())
    throw std::invalid_argument("--camera " + std::to_string(index) + ": the scene has " +
                                std::to_string(session.scene.cameras.size()) + " camera(s)");
}

}  // namespace sg::app
