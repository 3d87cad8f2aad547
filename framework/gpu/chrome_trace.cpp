#include <shadelgraph/gpu/chrome_trace.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace sg::gpu {

std::string toChromeTrace(const std::vector<TraceEvent>& events) {
  nlohmann::json trace = nlohmann::json::array();
  std::map<std::string, int> tracks;
  for (const auto& e : events) {
    auto [it, inserted] = tracks.emplace(e.track, int(tracks.size()) + 1);
    if (inserted)
      trace.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", it->second}, {"args", {{"name", e.track}}}});
    // Complete events ("X"); the format's times are in microseconds.
    trace.push_back({{"name", e.name}, {"ph", "X"}, {"pid", 1}, {"tid", it->second},
                     {"ts", e.startMs * 1000.0}, {"dur", e.durationMs * 1000.0}});
  }
  return nlohmann::json{{"traceEvents", trace}, {"displayTimeUnit", "ms"}}.dump(1);
}

void writeChromeTrace(const std::filesystem::path& file, const std::vector<TraceEvent>& events) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  errno = 0;
  std::ofstream out(file);
  if (out) out << toChromeTrace(events);
  // A full disk shows when the buffered bytes are written: check after flush and close.
  if (out) out.flush();
  if (out.is_open()) out.close();
  if (out.fail())
    throw std::runtime_error(file.string() + ": cannot write trace (" + (errno ? std::strerror(errno) : "write failed") +
                             ")");
}

}  // namespace sg::gpu
