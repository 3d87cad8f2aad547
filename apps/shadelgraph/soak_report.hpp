#pragma once
// render --soak-report FILE: the process's resident memory and frame times
// every N frames of a long run, as CSV, and a one-line summary comparing the
// end of the run with the end of warm-up. Shows leaks and slow drifts.
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <shadelgraph/gpu/graph_executor.hpp>

namespace sg::app {

// Resident set size of this process in bytes (Linux /proc/self/statm).
uint64_t residentBytes();

class SoakReport {
 public:
  // Rows every `every` frames of `frames`; warm-up is the first tenth of the run.
  SoakReport(std::string path, uint32_t every, uint32_t frames);
  // After frame `index` (0-based) has been rendered.
  void add(uint32_t index, const gpu::FrameTimings& timings);
  // Flushes the file (throws naming it if anything failed) and prints the summary.
  void finish();

 private:
  struct Row {
    uint32_t frame = 0;  // frames rendered so far
    uint64_t rss = 0;
    double frameMs = 0, gpuMs = 0;  // medians over the row's frames
  };
  std::string path_;
  std::ofstream out_;
  uint32_t every_, warmupFrames_;
  std::vector<double> frameMs_, gpuMs_;
  std::vector<Row> rows_;
};

}  // namespace sg::app
