#pragma once
// Per-label GPU timestamps (one query pair per scope) and a CPU stopwatch.
#include <chrono>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::gpu {

class Context;

struct TimedScope {
  std::string label;
  double gpuMs = 0.0;
  double startMs = 0.0;  // since the earliest scope read (for traces)
  uint64_t startNs = 0;  // the device's own clock, for ordering scopes of several frames
};

class GpuTimer {
 public:
  explicit GpuTimer(const Context& context, uint32_t maxScopes = 256);
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void reset();  // host-side reset; call before recording a frame
  uint32_t begin(VkCommandBuffer cmd, std::string label);
  void end(VkCommandBuffer cmd, uint32_t scope);
  // Waits for the results of every scope recorded since reset().
  std::vector<TimedScope> read() const;
  // Only these scopes (their results are awaited; the others are left zero,
  // e.g. work still running on another queue).
  std::vector<TimedScope> read(std::span<const uint32_t> scopes) const;
  uint32_t scopeCount() const { return static_cast<uint32_t>(labels_.size()); }

 private:
  VkDevice device_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  uint32_t maxScopes_;
  double nsPerTick_;
  std::vector<std::string> labels_;
};

class CpuTimer {
 public:
  CpuTimer() : start_(std::chrono::steady_clock::now()) {}
  double elapsedMs() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace sg::gpu
