// example-stripes: a material with one layer, procedural stripes lit by the
// frame's lights. Written only against the installed shadelgraph package.
#include <filesystem>

#include <shadelgraph/plugin/plugin_api.hpp>

namespace {

void registerStripes(sg::plugin::Registry* registry, const char* directory) {
  // shaders/example-stripes/stripes.glsl is installed beside this library;
  // the layer's source path is relative to that shader directory.
  registry->addShaderDirectory(std::filesystem::path(directory) / "shaders");
  registry->addLayer({.name = "stripes",
                      .source = "example-stripes/stripes.glsl",
                      .function = "stripes",
                      .parameters = {{"STRIPES_PER_UV", "12.0"}}});
  registry->addMaterial({.name = "example-stripes", .layers = {"stripes"}});
}

}  // namespace

SG_PLUGIN("example-stripes", registerStripes)
