#include "app_session.hpp"

#include <cstdio>

#include <CLI/CLI.hpp>

#include <builtin_materials.hpp>
#include <builtin_shaders.hpp>
#include <shadelgraph/plugin/plugin_loader.hpp>

#include "scene_source.hpp"

namespace sg::app {

std::vector<std::string> MaterialArgs::paths() const {
  std::vector<std::string> all = directories;
  all.insert(all.end(), libraries.begin(), libraries.end());
  return all;
}

void addMaterialOptions(CLI::App& command, MaterialArgs& args) {
  // Existence is checked by the loader, whose messages name the plugin.
  command.add_option("--plugin", args.libraries, "load a plugin library (.so); repeatable");
  command.add_option("--plugin-dir", args.directories, "load every plugin (*.so) of a directory; repeatable");
  command.add_option("--material", args.material,
                     "material (layer stack) of every object, e.g. bumps, skin, marble, debug-uv-checker, or a "
                     "plugin's (default: the scene's, else gltf-pbr)");
}

AppSession::AppSession(const std::string& scenePath, const std::string& mode, plugins::DecoupledSettings settings,
                       const MaterialArgs& materials) {
  // The built-ins, then the plugins (which may use built-in layers); a bad
  // plugin fails before the scene loads and the device starts.
  materials::registerBuiltinMaterials(registry);
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
  std::optional<scene::ShadingMode> override;
  if (!mode.empty()) override = scene::parseShadingMode(mode);
  // Before the upload: objects shaded decoupled without a chart get an automatic one.
  decoupled = std::make_unique<plugins::DecoupledShading>(plugins::chooseShading(scene, override), settings);
  context = std::make_unique<gpu::Context>();
  device = std::make_unique<gpu::Device>(*context);
  device->shaders().add(gpu::builtinShaders());
  renderer = std::make_unique<render::Renderer>(*device, scene, decoupled->recipe(), registry);
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
