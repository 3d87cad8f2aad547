#pragma once
// Loads plugin shared libraries (plugin_api.hpp) into a Registry. Every
// failure is a PluginError with one actionable line naming the library.
//
// Libraries stay loaded for the life of the process: what a plugin registers
// (PostPass::declare, the execute callbacks it adds to a graph) is its code.
#include <filesystem>
#include <string>
#include <vector>

#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugin {

struct LoadedPlugin {
  std::string name;               // SgPluginInfo::name
  std::filesystem::path library;  // the file loaded
};

// dlopen(RTLD_NOW | RTLD_LOCAL), check sg_plugin_info's ABI version, then
// registry.beginPlugin(name) and the plugin's register function with the
// library's directory.
LoadedPlugin loadPlugin(const std::filesystem::path& library, Registry& registry);

// Every *.so directly in `directory`, in name order (stops at the first error).
std::vector<LoadedPlugin> loadPluginDirectory(const std::filesystem::path& directory, Registry& registry);

// The directories of $SG_PLUGIN_PATH (colon-separated, empty entries ignored).
std::vector<std::filesystem::path> pluginPathDirectories();

// The plugins of every $SG_PLUGIN_PATH directory, then each of `paths` (a
// directory: its plugins; otherwise a plugin library).
std::vector<LoadedPlugin> loadPlugins(const std::vector<std::filesystem::path>& paths, Registry& registry);

}  // namespace sg::plugin
