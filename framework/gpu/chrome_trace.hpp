#pragma once
// Per-pass timings as a Chrome trace (the JSON "Trace Event Format"), which
// chrome://tracing and Perfetto open.
#include <filesystem>
#include <string>
#include <vector>

namespace sg::gpu {

struct TraceEvent {
  std::string name;
  std::string track;  // one row per track, e.g. "GPU graphics", "CPU record"
  double startMs = 0.0;
  double durationMs = 0.0;
};

std::string toChromeTrace(const std::vector<TraceEvent>& events);
void writeChromeTrace(const std::filesystem::path& file, const std::vector<TraceEvent>& events);

}  // namespace sg::gpu
