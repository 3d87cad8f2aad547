// A plugin whose registration fails: the loader must name it in the error.
#include <stdexcept>

#include <shadelgraph/plugin/plugin_api.hpp>

namespace {

void registerThrows(sg::plugin::Registry* registry, const char*) {
  registry->addLayer({.name = "half-registered", .source = "x.glsl", .function = "x"});
  throw std::runtime_error("cannot find its lookup table");
}

}  // namespace

SG_PLUGIN("test-throws", registerThrows)
