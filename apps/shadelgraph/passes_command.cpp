// shadelgraph passes [--json]: every registered pass (built-in or a plugin's)
// with its plugin, queue, the frame resources it reads and writes, and its
// parameters; then the registered frames. Needs no device.
#include <cstdio>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <builtin_plugins.hpp>
#include <shadelgraph/plugin/plugin_loader.hpp>

#include "app_session.hpp"
#include "commands.hpp"

namespace sg::app {
namespace {

nlohmann::json passJson(const plugin::PassPlugin& pass) {
  nlohmann::json parameters = nlohmann::json::array();
  for (const auto& p : pass.parameters)
    parameters.push_back({{"name", p.name}, {"default", p.defaultValue}, {"description", p.description}});
  return {{"name", pass.name},
          {"plugin", pass.plugin},
          {"queue", std::string(graph::toString(pass.queue))},
          {"reads", pass.reads},
          {"writes", pass.writes},
          {"parameters", parameters},
          {"description", pass.description}};
}

}  // namespace

void addPassesCommand(CLI::App& app) {
  struct Args {
    bool json = false;
    MaterialArgs plugins;
  };
  static Args args;
  auto* cmd = app.add_subcommand("passes", "List every registered pass and frame");
  cmd->add_flag("--json", args.json, "JSON");
  addMaterialOptions(*cmd, args.plugins);
  cmd->callback([] {
    plugin::Registry registry;
    plugins::registerBuiltins(registry);
    const auto paths = args.plugins.paths();
    plugin::loadPlugins({paths.begin(), paths.end()}, registry);
    if (args.json) {
      nlohmann::json passes = nlohmann::json::array(), frames = nlohmann::json::object();
      for (const auto& [name, pass] : registry.passes()) passes.push_back(passJson(pass));
      for (const auto& name : registry.frameNames()) {
        std::vector<std::string> order;
        for (const auto& p : plugin::resolveFrame(registry.frame(name), registry).passes) order.push_back(p.pass->name);
        frames[name] = order;
      }
      std::printf("%s\n", nlohmann::json{{"passes", passes}, {"frames", frames}}.dump(2).c_str());
      return;
    }
    for (const auto& [name, pass] : registry.passes()) {
      std::printf("%s  (%s, %s)\n  %s\n", name.c_str(), pass.plugin.c_str(), std::string(graph::toString(pass.queue)).c_str(),
                  pass.description.c_str());
      std::printf("  reads:  %s\n  writes: %s\n", plugin::join(pass.reads).c_str(), plugin::join(pass.writes).c_str());
      for (const auto& p : pass.parameters)
        std::printf("  parameter %s = %s: %s\n", p.name.c_str(), p.defaultValue.dump().c_str(), p.description.c_str());
    }
    for (const auto& name : registry.frameNames()) {
      std::string order;
      for (const auto& p : plugin::resolveFrame(registry.frame(name), registry).passes)
        order += (order.empty() ? "" : " -> ") + p.pass->name;
      std::printf("frame %s: %s\n", name.c_str(), order.c_str());
    }
  });
}

}  // namespace sg::app
