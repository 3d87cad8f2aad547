#pragma once
// The last frames' GPU time of each pass, for the timing panel's graphs.
#include <deque>
#include <map>
#include <string>
#include <vector>

#include <shadelgraph/gpu/graph_executor.hpp>

namespace sg::app::view {

class TimingHistory {
 public:
  static constexpr size_t kFrames = 120;
  void add(const gpu::FrameTimings& timings) {
    for (const auto& pass : timings.passes) {
      auto& h = gpuMs_[pass.name];
      h.push_back(float(pass.gpuMs));
      if (h.size() > kFrames) h.erase(h.begin());
    }
  }
  const std::vector<float>& of(const std::string& pass) const {
    static const std::vector<float> none;
    const auto it = gpuMs_.find(pass);
    return it == gpuMs_.end() ? none : it->second;
  }

 private:
  std::map<std::string, std::vector<float>> gpuMs_;
};

}  // namespace sg::app::view
