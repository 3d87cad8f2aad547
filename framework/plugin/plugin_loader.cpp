#include <shadelgraph/plugin/plugin_loader.hpp>

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <optional>

#include <shadelgraph/plugin/plugin_api.hpp>

namespace sg::plugin {
namespace {

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// RTLD_LOCAL: two plugins may define the same helper symbols without one
// silently using the other's. RTLD_NOW: a plugin needing a framework symbol
// this build lacks fails here, with the symbol's name, not mid-frame.
void* openLibrary(const std::filesystem::path& library) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(library, ec))
    throw PluginError("plugin " + quoted(library) + ": no such file");
  dlerror();  // clear a stale message
  void* handle = dlopen(std::filesystem::absolute(library).c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw PluginError("plugin " + quoted(library) + " cannot be loaded: " + (why ? why : "unknown dlopen error"));
  }
  // Never dlclose'd: the registry holds the plugin's functions (see header).
  return handle;
}

}  // namespace

LoadedPlugin loadPlugin(const std::filesystem::path& library, Registry& registry) {
  void* handle = openLibrary(library);
  auto entry = reinterpret_cast<SgPluginInfoFunction>(dlsym(handle, SG_PLUGIN_ENTRY_POINT));
  if (!entry)
    throw PluginError(quoted(library) + " is not a shadelgraph plugin: it exports no " SG_PLUGIN_ENTRY_POINT
                      " (define it with SG_PLUGIN from <shadelgraph/plugin/plugin_api.hpp>)");
  const SgPluginInfo* info = entry();
  if (!info) throw PluginError(quoted(library) + ": " SG_PLUGIN_ENTRY_POINT " returned null");
  // abiVersion is the first member in every ABI version; nothing else is read
  // before it matches.
  if (info->abiVersion != SG_PLUGIN_ABI_VERSION)
    throw PluginError(quoted(library) + " was built for plugin ABI " + std::to_string(info->abiVersion) +
                      ", this shadelgraph has " + std::to_string(SG_PLUGIN_ABI_VERSION) +
                      ": rebuild it against this version");
  if (!info->name || !*info->name || !info->registerPlugin)
    throw PluginError(quoted(library) + ": its " SG_PLUGIN_ENTRY_POINT " has no name or no register function");

  LoadedPlugin loaded{info->name, library};
  const std::string directory = std::filesystem::absolute(library).parent_path().string();
  // Credit the plugin with what it registers, then whoever registered before
  // (the host) again, so later registrations are not misattributed.
  const std::string previous = registry.currentPlugin();
  registry.beginPlugin(loaded.name);
  std::optional<std::string> failure;
  try {
    info->registerPlugin(&registry, directory.c_str());
  } catch (const std::exception& e) {
    failure = e.what();
  } catch (...) {
    failure = "its register function threw something that is not a std::exception";
  }
  registry.beginPlugin(previous);
  if (failure) throw PluginError("plugin '" + loaded.name + "' (" + library.string() + "): " + *failure);
  return loaded;
}

std::vector<LoadedPlugin> loadPluginDirectory(const std::filesystem::path& directory, Registry& registry) {
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec))
    throw PluginError("plugin directory " + quoted(directory) + ": no such directory");
  std::vector<std::filesystem::path> libraries;
  for (const auto& entry : std::filesystem::directory_iterator(directory))
    if (entry.path().extension() == ".so" && entry.is_regular_file()) libraries.push_back(entry.path());
  // Name order: registration order (and so duplicate-name errors) does not
  // depend on the file system's.
  std::sort(libraries.begin(), libraries.end(),
            [](const auto& a, const auto& b) { return a.filename() < b.filename(); });
  std::vector<LoadedPlugin> loaded;
  for (const auto& library : libraries) loaded.push_back(loadPlugin(library, registry));
  return loaded;
}

std::vector<std::filesystem::path> pluginPathDirectories() {
  std::vector<std::filesystem::path> directories;
  const char* value = std::getenv("SG_PLUGIN_PATH");
  if (!value) return directories;
  std::string rest = value;
  while (!rest.empty()) {
    const size_t colon = rest.find(':');
    const std::string entry = rest.substr(0, colon);
    if (!entry.empty()) directories.emplace_back(entry);
    rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
  }
  return directories;
}

std::vector<LoadedPlugin> loadPlugins(const std::vector<std::filesystem::path>& paths, Registry& registry) {
  std::vector<LoadedPlugin> loaded;
  for (const auto& directory : pluginPathDirectories()) {
    std::error_code ec;
    // A missing directory here is a mistake in the environment, not on the
    // command line: say where it came from.
    if (!std::filesystem::is_directory(directory, ec))
      throw PluginError("$SG_PLUGIN_PATH names " + quoted(directory) + ", which is not a directory");
    for (auto& plugin : loadPluginDirectory(directory, registry)) loaded.push_back(std::move(plugin));
  }
  for (const auto& path : paths) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
      for (auto& plugin : loadPluginDirectory(path, registry)) loaded.push_back(std::move(plugin));
    } else {
      loaded.push_back(loadPlugin(path, registry));
    }
  }
  return loaded;
}

}  // namespace sg::plugin
