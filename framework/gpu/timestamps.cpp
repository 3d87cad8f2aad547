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
  std::vector<uint32_t> all(labels_.size());
  for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  return read(all);
}

std::vector<TimedScope> GpuTimer::read(std::span<const uint32_t> scopes) const {
  std::vector<TimedScope> out(labels_.size());
  for (size_t i = 0; i < labels_.size(); ++i) out[i].label = labels_[i];
  if (scopes.empty()) return out;
  std::vector<uint64_t> ticks(labels_.size() * 2, 0);
  // Consecutive scopes in one call each (a frame's are usually one run).
  for (size_t i = 0; i < scopes.size();) {
    size_t j = i + 1;
    while (j < scopes.size() && scopes[j] == scopes[j - 1] + 1) ++j;
    const uint32_t first = scopes[i], count = uint32_t(j - i) * 2;
    // Without WAIT first, per query: the caller has waited for these
    // scopes' work, and lavapipe's WAIT waits for everything submitted (a
    // frame's tail included). A query not yet available is then waited for.
    std::vector<uint64_t> withAvailability(size_t(count) * 2);
    const VkResult ready = vkGetQueryPoolResults(device_, pool_, first * 2, count, withAvailability.size() * 8,
                                                 withAvailability.data(), 16,
                                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WITH_AVAILABILITY_BIT);
    bool available = ready == VK_SUCCESS || ready == VK_NOT_READY;
    for (uint32_t q = 0; available && q < count; ++q) available = withAvailability[2 * q + 1] != 0;
    if (available) {
      for (uint32_t q = 0; q < count; ++q) ticks[first * 2 + q] = withAvailability[2 * q];
    } else {
      SG_VK(vkGetQueryPoolResults(device_, pool_, first * 2, count, count * 8, ticks.data() + first * 2, 8,
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    }
    i = j;
  }
  uint64_t earliest = ticks[scopes[0] * 2];
  for (const uint32_t i : scopes) earliest = std::min(earliest, ticks[2 * i]);
  for (const uint32_t i : scopes) {
    out[i].gpuMs = static_cast<double>(ticks[2 * i + 1] - ticks[2 * i]) * nsPerTick_ * 1e-6;
    out[i].startMs = static_cast<double>(ticks[2 * i] - earliest) * nsPerTick_ * 1e-6;
    out[i].startNs = static_cast<uint64_t>(static_cast<double>(ticks[2 * i]) * nsPerTick_);
  }
  return out;
}

}  // namespace sg::gpu
