// A plugin whose layer's GLSL does not compile (shaders/broken-glsl/broken.glsl,
// line 6): rendering with its material must fail with that file and line.
#include <filesystem>

#include <shadelgraph/plugin/plugin_api.hpp>

namespace {

void registerBroken(sg::plugin::Registry* registry, const char* directory) {
  registry->addShaderDirectory(std::filesystem::path(directory) / "shaders");
  registry->addLayer({.name = "broken", .source = "broken-glsl/broken.glsl", .function = "brokenLayer"});
  registry->addMaterial({.name = "broken", .layers = {"broken"}});
}

}  // namespace

SG_PLUGIN("test-broken-glsl", registerBroken)
