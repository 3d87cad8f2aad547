// shadelgraph: the headless command line. Every error ends in one line on
// stderr and a non-zero exit code.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "commands.hpp"

namespace sg::app {
namespace {
int gExitCode = 0;
}
int exitCode() { return gExitCode; }
void setExitCode(int code) { gExitCode = code; }
}  // namespace sg::app

int main(int argc, char** argv) {
  CLI::App app{"shadelgraph: a render graph with generalized decoupled shading"};
  app.set_version_flag("--version", SG_VERSION);
  app.require_subcommand(1);
  sg::app::addRenderCommand(app);
  sg::app::addGraphCommand(app);
  sg::app::addInspectCommand(app);
  sg::app::addBenchCommand(app);
  sg::app::addPassesCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadelgraph: error: %s\n", e.what());
    return 1;
  }
  return sg::app::exitCode();
}
