// A plugin built for another plugin ABI: the loader must refuse it before
// reading anything but the version.
#include <shadelgraph/plugin/plugin_api.hpp>

namespace {
void registerNothing(sg::plugin::Registry*, const char*) {}
}  // namespace

extern "C" __attribute__((visibility("default"))) const SgPluginInfo* sg_plugin_info(void) {
  static const SgPluginInfo info{999u, "test-wrong-abi", registerNothing};
  return &info;
}
