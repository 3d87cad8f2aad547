#pragma once
// shadelgraph bench targets: every row of issue 14's table of targets measured
// in one run, each figure judged against its target (bench_targets_table.hpp).
// Writes targets.json and targets.md and prints the summary.
#include <filesystem>

#include "command_options.hpp"

namespace sg::app {

// Checks the options and reads --baseline-json before the device starts;
// sets the exit code to 1 when the validation layer reported anything.
void runTargetsBench(const TargetsBenchArgs& args, const std::filesystem::path& out);

}  // namespace sg::app
