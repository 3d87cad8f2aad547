#include <shadelgraph/gpu/timestamps.hpp>

#include <algorithm>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {

GpuTimer::GpuTimer(const Context& context, uint32_t maxScopes)
    : device_(context.device()), maxScopes_(maxScopes),
      nsPerTick_(static_cast<double>(context.properties().limits.timestampPeriod)) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = maxScopes * 2;
  SG_VK(vkCreateQueryPool(device_, &info, nullptr, &pool_));
  reset();
}

GpuTimer::~GpuTimer() { vkDestroyQueryPool(device_, pool_, nullptr); }

void GpuTimer::reset() {
  vkResetQueryPool(device_, pool_, 0, maxScopes_ * 2);
  labels_.clear();
}

uint32_t GpuTimer::begin(VkCommandBuffer cmd, std::string label) {
  if (labels_.size() >= maxScopes_) throw GpuError("GpuTimer: more than " + std::to_string(maxScopes_) + " scopes");
  const auto scope = static_cast<uint32_t>(labels_.size());
  labels_.push_back(std::move(label));
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, scope * 2);
  return scope;
}

void GpuTimer::end(VkCommandBuffer cmd, uint32_t scope) {
  vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, scope * 2 + 1);
}

std::vector<TimedScope> GpuTimer::read() const {
  std::vector<TimedScope> out;
  if (labels_.empty()) return out;
  std::vector<uint64_t> ticks(labels_.size() * 2);
  SG_VK(vkGetQueryPoolResults(device_, pool_, 0, static_cast<uint32_t>(ticks.size()), ticks.size() * 8, ticks.data(),
                              8, VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  uint64_t first = ticks[0];
  for (size_t i = 0; i < labels_.size(); ++i) first = std::min(first, ticks[2 * i]);
  for (size_t i = 0; i < labels_.size(); ++i)
    out.push_back({labels_[i], static_cast<double>(ticks[2 * i + 1] - ticks[2 * i]) * nsPerTick_ * 1e-6,
                   static_cast<double>(ticks[2 * i] - first) * nsPerTick_ * 1e-6});
  return out;
}

}  // namespace sg::gpu
