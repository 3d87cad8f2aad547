// shadelgraph: the headless command line. Every error ends in one line on
// stderr and a non-zero exit code.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <string>

#include "commands.hpp"
#include "heap_policy.hpp"

namespace sg::app {
namespace {
int gExitCode = 0;

// One line, whatever the message holds (some CLI11 messages span lines).
int fail(std::string what) {
  for (char& c : what)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "shadelgraph: error: %s\n", what.c_str());
  return 1;
}
}  // namespace
int exitCode() { return gExitCode; }
void setExitCode(int code) { gExitCode = code; }
}  // namespace sg::app

int main(int argc, char** argv) {
  sg::app::keepFreedHeapMemory();
  CLI::App app{"shadelgraph: a render graph with generalized decoupled shading"};
  app.set_version_flag("--version", SG_VERSION);
  app.require_subcommand(1);
  sg::app::addRenderCommand(app);
  sg::app::addGraphCommand(app);
  sg::app::addInspectCommand(app);
  sg::app::addBenchCommand(app);
  sg::app::addPassesCommand(app);
  sg::app::addViewCommand(app);
  try {
    // CLI11 would only say that a subcommand is required: name the unknown one.
    if (argc > 1 && argv[1][0] != '-') {
      std::string known;
      bool found = false;
      for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
        found |= sub->get_name() == argv[1];
        known += (known.empty() ? "" : ", ") + sub->get_name();
      }
      if (!found) return sg::app::fail(std::string("unknown command '") + argv[1] + "' (commands: " + known + ")");
    }
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version arrive as "errors" with exit code 0: CLI11 prints them.
    if (e.get_exit_code() == 0) return app.exit(e);
    return sg::app::fail(e.what());
  } catch (const std::exception& e) {
    return sg::app::fail(e.what());
  }
  // What went to stdout (a plan, a table) must have arrived: a full disk is an error too.
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) return sg::app::fail("stdout: write failed");
  return sg::app::exitCode();
}
