#pragma once
// Per-label GPU timestamps (one query pair per scope) and a CPU stopwatch.
#include <chrono>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::gpu {

class Context;

struct TimedScope {
  std::string label;
  double gpuMs = 0.0;
  double startMs = 0.0;  // since the earliest scope of the frame (for traces)
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
