#include "app_session.hpp"

#include <cstdio>

#include <builtin_shaders.hpp>

#include "scene_source.hpp"

namespace sg::app {

AppSession::AppSession(const std::string& scenePath, const std::string& mode, plugins::DecoupledSettings settings) {
  auto loaded = loadSceneArgument(scenePath);
  scene = std::move(loaded.scene);
  cameraPaths = std::move(loaded.cameraPaths);
  std::optional<scene::ShadingMode> override;
  if (!mode.empty()) override = scene::parseShadingMode(mode);
  // Before the upload: objects shaded decoupled without a chart get an automatic one.
  decoupled = std::make_unique<plugins::DecoupledShading>(plugins::chooseShading(scene, override), settings);
  context = std::make_unique<gpu::Context>();
  device = std::make_unique<gpu::Device>(*context);
  device->shaders().add(gpu::builtinShaders());
  renderer = std::make_unique<render::Renderer>(*device, scene, decoupled->recipe());
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
