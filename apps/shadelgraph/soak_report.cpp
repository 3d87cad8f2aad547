#include "soak_report.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace sg::app {
namespace {

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
  return v[v.size() / 2];
}

double mib(uint64_t bytes) { return double(bytes) / double(1 << 20); }

}  // namespace

uint64_t residentBytes() {
  FILE* statm = std::fopen("/proc/self/statm", "r");
  if (!statm) return 0;
  unsigned long long size = 0, resident = 0;
  const int read = std::fscanf(statm, "%llu %llu", &size, &resident);
  std::fclose(statm);
  return read == 2 ? resident * uint64_t(sysconf(_SC_PAGESIZE)) : 0;
}

SoakReport::SoakReport(std::string path, uint32_t every, uint32_t frames)
    : path_(std::move(path)), every_(every), warmupFrames_(std::max(every, frames / 10)) {
  if (std::filesystem::path(path_).has_parent_path())
    std::filesystem::create_directories(std::filesystem::path(path_).parent_path());
  out_.open(path_);
  if (!out_) throw std::runtime_error(path_ + ": cannot write soak report (" + std::strerror(errno) + ")");
  out_ << "frame,rss_mib,frame_ms,gpu_ms\n";
}

void SoakReport::add(uint32_t index, const gpu::FrameTimings& timings) {
  frameMs_.push_back(timings.frameMs);
  gpuMs_.push_back(timings.gpuMs);
  if ((index + 1) % every_ != 0) return;
  const Row row{index + 1, residentBytes(), medianOf(frameMs_), medianOf(gpuMs_)};
  frameMs_.clear();
  gpuMs_.clear();
  char line[128];
  std::snprintf(line, sizeof line, "%u,%.2f,%.4f,%.4f\n", row.frame, mib(row.rss), row.frameMs, row.gpuMs);
  out_ << line << std::flush;  // a long run can be watched, and a full disk fails early
  if (!out_) throw std::runtime_error(path_ + ": cannot write soak report (" + std::strerror(errno) + ")");
  rows_.push_back(row);
}

void SoakReport::finish() {
  errno = 0;
  out_.flush();
  out_.close();
  if (out_.fail())
    throw std::runtime_error(path_ + ": cannot write soak report (" + (errno ? std::strerror(errno) : "write failed") + ")");
  if (rows_.empty()) return;
  // The first row at or after warm-up; the last row.
  const auto warm = std::find_if(rows_.begin(), rows_.end(), [&](const Row& r) { return r.frame >= warmupFrames_; });
  const Row& start = warm != rows_.end() ? *warm : rows_.back();
  const Row& end = rows_.back();
  std::printf("soak: RSS %.1f MiB at frame %u (after warm-up) -> %.1f MiB at frame %u (%+.2f%%); frame ms %.3f -> %.3f, "
              "GPU ms %.3f -> %.3f (medians of %u frames); wrote %s\n",
              mib(start.rss), start.frame, mib(end.rss), end.frame,
              start.rss ? 100.0 * (double(end.rss) - double(start.rss)) / double(start.rss) : 0.0, start.frameMs,
              end.frameMs, start.gpuMs, end.gpuMs, every_, path_.c_str());
}

}  // namespace sg::app
