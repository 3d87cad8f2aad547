// shadelgraph graph [scene]: the compiled plan of the frame `render` would run,
// as text (default), Graphviz DOT or JSON. Memory offsets come from the real
// device's requirements, so a device is created.
#include <cstdio>

#include <shadelgraph/graph/plan_dump.hpp>

#include "app_session.hpp"
#include "commands.hpp"
#include "option_checks.hpp"

namespace sg::app {

void addGraphCommand(CLI::App& app) {
  struct Args {
    std::string scene;
    std::string size = "1280x720";
    std::string mode;
    bool dot = false, json = false, noAliasing = false;
    MaterialArgs materials;
    FrameArgs frame;
  };
  static Args args;
  auto* cmd = app.add_subcommand("graph", "Print the compiled render graph of the frame 'render' would run");
  cmd->add_option("scene", args.scene, "a .gltf/.glb/.json scene (default: the built-in scene)");
  cmd->add_option("--size", args.size, "WIDTHxHEIGHT, each side 1 to " + std::to_string(kMaxOutputSide))
      ->capture_default_str();
  cmd->add_option("--mode", args.mode, "shading of every object: forward, decoupled, auto (default: each object's own)")
      ->check(CLI::IsMember({"forward", "decoupled", "auto"}));
  auto* dot = cmd->add_flag("--dot", args.dot, "Graphviz DOT");
  cmd->add_flag("--json", args.json, "JSON")->excludes(dot);
  cmd->add_flag("--no-aliasing", args.noAliasing, "give every transient its own memory");
  addMaterialOptions(*cmd, args.materials);
  addFrameOptions(*cmd, args.frame);
  cmd->callback([] {
    render::RenderSettings settings;
    parseSize("--size", args.size, settings.width, settings.height);
    settings.aliasing = !args.noAliasing;
    AppSession session(args.scene, args.mode, {}, args.materials, args.frame);
    const auto plan = session.renderer->plan(settings);
    const std::string text = args.dot ? graph::toDot(plan) : args.json ? graph::toJson(plan) : graph::toText(plan);
    std::fwrite(text.data(), 1, text.size(), stdout);
    setExitCode(session.validationExitCode());
  });
}

}  // namespace sg::app
