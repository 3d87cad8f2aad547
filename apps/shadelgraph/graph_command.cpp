// shadelgraph graph [scene]: the compiled plan of the frame `render` would run,
// as text (default), Graphviz DOT or JSON. Memory offsets come from the real
// device's requirements, so a device is created.
#include <cstdio>

#include <shadelgraph/graph/plan_dump.hpp>

#include "app_session.hpp"
#include "command_options.hpp"
#include "commands.hpp"
#include "option_checks.hpp"

namespace sg::app {

void addGraphCommand(CLI::App& app) {
  static GraphArgs args;
  auto* cmd = app.add_subcommand("graph", "Print the compiled render graph of the frame 'render' would run");
  addGraphOptions(*cmd, args);
  cmd->callback([] {
    checkGraphArgs(args);
    render::RenderSettings settings;
    parseSize("--size", args.size, settings.width, settings.height);
    settings.aliasing = !args.noAliasing;
    if (!args.pick.empty()) settings.pick = glm::uvec2(uint32_t(args.pick[0]), uint32_t(args.pick[1]));
    AppSession session(args.scene, args.mode, {}, args.materials, args.frame);
    const auto plan = session.renderer->plan(settings);
    const std::string text = args.dot ? graph::toDot(plan) : args.json ? graph::toJson(plan) : graph::toText(plan);
    std::fwrite(text.data(), 1, text.size(), stdout);
    setExitCode(session.validationExitCode());
  });
}

}  // namespace sg::app
