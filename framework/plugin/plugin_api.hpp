#pragma once
// The entry point of a plugin shared library. A plugin defines it with
// SG_PLUGIN("name", registerFunction); the loader (plugin_loader.hpp) finds
// `sg_plugin_info`, checks the ABI version and calls `registerPlugin`.
//
// The ABI version changes whenever Registry, MaterialLayer, MaterialStack or
// PassPlugin or FrameDescription change layout: a plugin built against other headers is refused.
#include <cstdint>

#include <shadelgraph/plugin/registry.hpp>

#define SG_PLUGIN_ABI_VERSION 4u  // 4: MaterialLayer::dependsOn, refreshShadeFrames

extern "C" {

struct SgPluginInfo {
  uint32_t abiVersion;  // SG_PLUGIN_ABI_VERSION the plugin was built with
  const char* name;
  // Registers the plugin's layers, materials and passes. `directory`: the
  // folder of the shared library (for its GLSL files).
  void (*registerPlugin)(sg::plugin::Registry* registry, const char* directory);
};

typedef const SgPluginInfo* (*SgPluginInfoFunction)(void);
}

#define SG_PLUGIN_ENTRY_POINT "sg_plugin_info"

#define SG_PLUGIN(pluginName, registerFunction)                                     \
  extern "C" __attribute__((visibility("default"))) const SgPluginInfo* sg_plugin_info(void) { \
    static const SgPluginInfo info{SG_PLUGIN_ABI_VERSION, pluginName, registerFunction}; \
    return &info;                                                                   \
  }
