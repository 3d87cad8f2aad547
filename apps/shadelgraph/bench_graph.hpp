#pragma once
// shadelgraph bench graph: what declaring and compiling a render graph costs as
// it grows (synthetic graphs of 10, 100, 1000 passes). No device needed.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sg::app {

struct GraphBenchArgs {
  std::vector<uint32_t> passes{10, 100, 1000};
  uint32_t graphs = 8;        // distinct graphs per size
  uint32_t repetitions = 40;  // timed rounds; each compiles every graph of every size once per mode
};

// Writes graph.json and graph.csv into `out` and prints medians and ratios.
void runGraphBench(const GraphBenchArgs& args, const std::filesystem::path& out);

}  // namespace sg::app
