#pragma once
// shadelgraph bench graph: what declaring and compiling a render graph costs as
// it grows (synthetic graphs of 10, 100, 1000 passes). No device needed.
#include <cstdint>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

namespace sg::app {

struct GraphBenchArgs {
  std::vector<uint32_t> passes{10, 100, 1000};
  uint32_t graphs = 8;        // distinct graphs per size
  uint32_t repetitions = 40;  // timed rounds; each compiles every graph of every size once per mode
};

// The measurement alone: {"sizes": [{passes, kept_passes_mean, samples,
// fresh: {median_us, p10_us, p90_us, per_pass_ns}, reused: {...}}],
// "ratios": [{passes, over, fresh, reused}]}; throws on empty or too small sizes.
nlohmann::json measureGraphCompile(const GraphBenchArgs& args);

// Writes graph.json and graph.csv into `out` and prints medians and ratios.
void runGraphBench(const GraphBenchArgs& args, const std::filesystem::path& out);

}  // namespace sg::app
