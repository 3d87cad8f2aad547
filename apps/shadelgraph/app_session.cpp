#include "app_session.hpp"

#include <cstdio>

#include <builtin_shaders.hpp>
#include <forward/forward_recipe.hpp>

#include "scene_source.hpp"

namespace sg::app {

AppSession::AppSession(const std::string& scenePath) {
  auto loaded = loadSceneArgument(scenePath);
  scene = std::move(loaded.scene);
  cameraPaths = std::move(loaded.cameraPaths);
  context = std::make_unique<gpu::Context>();
  device = std::make_unique<gpu::Device>(*context);
  device->shaders().add(gpu::builtinShaders());
  renderer = std::make_unique<render::Renderer>(*device, scene, plugins::forwardRecipe);
}

AppSession::~AppSession() {
  renderer.reset();
  device.reset();
}

int AppSession::validationExitCode() const {
  const size_t n = context->validationLog().count();
  if (n == 0) return 0;
  std::fprintf(stderr, "shadelgraph: error: %zu validation message(s), see above\n", n);
  return 1;
}

}  // namespace sg::app
