#include "app_session.hpp"

#include <cstdio>
#include <filesystem>

#include <builtin_plugins.hpp>
#include <builtin_shaders.hpp>
#include <decoupled/decoupled_package.hpp>
#include <shadelgraph/plugin/plugin_loader.hpp>

#include "scene_source.hpp"

namespace sg::app {

namespace {

plugin::ResolvedFrame chooseFrame(const plugin::Registry& registry, const std::string& frameGraph) {
  if (frameGraph.empty()) return plugin::resolveFrame(registry.frame("decoupled"), registry);
  if (registry.hasFrame(frameGraph)) return plugin::resolveFrame(registry.frame(frameGraph), registry);
  if (!std::filesystem::exists(frameGraph))
    throw plugin::FrameError("--frame-graph " + frameGraph + ": no such file, and no frame of that name (known: " +
                             plugin::join(registry.frameNames()) + ")");
  return plugin::resolveFrame(plugin::loadFrameDescription(frameGraph), registry);
}

// "name=mode" onto the scene's instances (every instance of that name).
void applyObjectModes(scene::Scene& scene, const std::vector<std::string>& modes) {
  for (const auto& item : modes) {
    const auto eq = item.find('=');
    const auto mode = eq == std::string::npos ? std::nullopt : scene::parseShadingMode(item.substr(eq + 1));
    if (!mode) throw std::invalid_argument("--object-mode " + item + ": expected NAME=forward|decoupled|auto");
    const std::string name = item.substr(0, eq);
    bool found = false;
    for (auto& instance : scene.instances)
      if (instance.name == name) {
        instance.shading = *mode;
        found = true;
      }
    if (!found) throw std::invalid_argument("--object-mode " + item + ": the scene has no object '" + name + "'");
  }
}

}  // namespace

AppSession::AppSession(const std::string& scenePath, const std::string& mode, plugins::DecoupledSettings settings,
                       const MaterialArgs& materials, const FrameArgs& frame,
                       const gpu::ContextOptions& contextOptions) {
  // The built-ins, then the plugins (which may use built-in layers and
  // passes); a bad plugin fails before the scene loads and the device starts.
  plugins::registerBuiltins(registry);
  const auto paths = materials.paths();
  const auto plugged = plugin::loadPlugins({paths.begin(), paths.end()}, registry);
  for (const auto& p : plugged) std::fprintf(stderr, "plugin '%s': %s\n", p.name.c_str(), p.library.c_str());
  auto loaded = loadSceneArgument(scenePath);
  scene = std::move(loaded.scene);
  cameraPaths = std::move(loaded.cameraPaths);
  if (!materials.material.empty()) {
    registry.material(materials.material);  // an unknown name fails here, listing the known ones
    for (auto& instance : scene.instances) instance.material = materials.material;
  }
  // A frame that cannot work fails before the device starts.
  auto resolved = chooseFrame(registry, frame.frameGraph);
  if (!mode.empty())
    for (auto& instance : scene.instances) instance.shading = *scene::parseShadingMode(mode);
  applyObjectModes(scene, frame.objectModes);
  context = std::make_unique<gpu::Context>(contextOptions);
  device = std::make_unique<gpu::Device>(*context);
  device->shaders().add(gpu::builtinShaders());
  auto made = plugins::makeDecoupledRenderer(*device, scene, registry, std::move(resolved), std::nullopt, settings);
  decoupled = std::move(made.shading);
  renderer = std::move(made.renderer);
}

void AppSession::rebuildRenderer(const plugins::DecoupledSettings& settings) {
  auto frame = renderer->frame();
  renderer->finishFrames();
  vkDeviceWaitIdle(device->context().device());
  renderer.reset();
  decoupled.reset();
  auto made = plugins::makeDecoupledRenderer(*device, scene, registry, std::move(frame), std::nullopt, settings);
  decoupled = std::move(made.shading);
  renderer = std::move(made.renderer);
}

AppSession::~AppSession() {
  renderer.reset();
  decoupled.reset();
  device.reset();
}

int AppSession::validationExitCode() const {
  const size_t n = context->validationLog().count();
  if (n == 0) return 0;
  std::fprintf(stderr, "shadelgraph: error: %zu validation message(s), see above\n", n);
  return 1;
}

}  // namespace sg::app
