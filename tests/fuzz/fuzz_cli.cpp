// libFuzzer target: command-line parsing. The input is an argument vector,
// one argument per line. It builds the CLI11 app as apps/shadelgraph/main.cpp
// does and parses with CLI11's real option handling: 'inspect' runs; the
// device commands (render, graph, bench) get their real option sets and
// checks (command_options.cpp) and stop before they would start a device. A bare file name of the glTF seed corpus ('inspect Box.glb')
// names that model. Contract: CLI::ParseError or std::exception
// (main.cpp turns both into one line and exit 1); nothing else.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "command_options.hpp"
#include "commands.hpp"

namespace {

constexpr size_t kMaxArguments = 64;

bool setUp() {
  // inspect prints a report per run; the fuzzer's own output is on stderr.
  if (!std::freopen("/dev/null", "w", stdout)) {
    std::perror("fuzz_cli: setup");
    std::abort();
  }
  return true;
}

// Paths into the kernel's pseudo-files are no glTF files and can block or be
// huge; the loader is fuzzed on its own by fuzz_gltf.
bool harmless(std::string_view argument) {
  for (std::string_view prefix : {"/proc", "/dev", "/sys"})
    if (argument.find(prefix) != std::string_view::npos) return false;
  return true;
}

// "Box.glb" -> the seed model of that name, when there is one.
std::string resolveModel(std::string argument) {
  if (argument.empty() || argument.find('/') != std::string::npos) return argument;
  std::error_code error;
  const auto model = std::filesystem::path(SG_FUZZ_MODELS_DIR) / argument;
  return std::filesystem::is_regular_file(model, error) ? model.string() : argument;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool ready = setUp();
  (void)ready;
  std::vector<std::string> arguments{"shadelgraph"};
  std::string_view text(reinterpret_cast<const char*>(data), size);
  while (!text.empty() && arguments.size() < kMaxArguments) {
    const size_t end = text.find('\n');
    if (!harmless(text.substr(0, end))) return 0;
    arguments.push_back(resolveModel(std::string(text.substr(0, end))));
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
  }
  std::vector<char*> argv;
  for (auto& a : arguments) argv.push_back(a.data());

  // As main.cpp sets it up.
  CLI::App app{"shadelgraph: a render graph with generalized decoupled shading"};
  app.set_version_flag("--version", "0");
  app.require_subcommand(1);
  sg::app::addInspectCommand(app);
  // The device commands with their real option sets and checks
  // (command_options.cpp); what they would then run needs a device.
  sg::app::RenderArgs render;
  auto* renderCommand = app.add_subcommand("render");
  sg::app::addRenderOptions(*renderCommand, render);
  renderCommand->callback([&] { sg::app::checkRenderArgs(render); });
  sg::app::GraphArgs graph;
  auto* graphCommand = app.add_subcommand("graph");
  sg::app::addGraphOptions(*graphCommand, graph);
  graphCommand->callback([&] { sg::app::checkGraphArgs(graph); });
  sg::app::BenchArgs bench;
  sg::app::GraphBenchArgs graphBench;
  auto* benchCommand = app.add_subcommand("bench");
  sg::app::addBenchOptions(*benchCommand, bench, graphBench);
  sg::app::TargetsBenchArgs targetsBench;
  auto* targetsCommand = sg::app::addBenchTargetsOptions(*benchCommand, targetsBench);
  targetsCommand->callback([&] { sg::app::checkBenchTargetsArgs(targetsBench); });
  benchCommand->callback([&] {
    if (!benchCommand->got_subcommand("graph") && !benchCommand->got_subcommand("targets"))
      sg::app::checkBenchArgs(bench);
  });
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError&) {
  } catch (const std::exception&) {
  }
  return 0;
}
