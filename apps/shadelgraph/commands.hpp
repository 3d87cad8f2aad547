#pragma once
// The subcommands of the shadelgraph CLI; each registers itself on the CLI11 app
// and runs from its callback.
#include <CLI/CLI.hpp>

namespace sg::app {

void addRenderCommand(CLI::App& app);
void addGraphCommand(CLI::App& app);
void addInspectCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addPassesCommand(CLI::App& app);
void addViewCommand(CLI::App& app);

// Set by a command that finished but must report failure (e.g. validation messages).
int exitCode();
void setExitCode(int code);

}  // namespace sg::app
