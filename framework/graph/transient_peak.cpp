#include <shadelgraph/graph/transient_peak.hpp>

#include <algorithm>

namespace sg::graph {

TransientPeak transientPeak(const CompiledPlan& plan) {
  // Bytes starting and ending at each position, then a running sum.
  std::vector<int64_t> delta(plan.order.size() + 1, 0);
  for (const PlannedResource& r : plan.resources) {
    if (!isTransient(r.kind) || r.culled || !r.memory.placed() || r.firstUse >= plan.order.size()) continue;
    delta[r.firstUse] += int64_t(r.memory.size);
    delta[std::min<size_t>(r.lastUse, plan.order.size() - 1) + 1] -= int64_t(r.memory.size);
  }
  TransientPeak peak;
  int64_t inUse = 0;
  for (uint32_t p = 0; p < plan.order.size(); ++p) {
    inUse += delta[p];
    if (inUse > 0 && uint64_t(inUse) > peak.bytes) {
      peak.bytes = uint64_t(inUse);
      peak.position = p;
    }
  }
  if (peak.position == kInvalidIndex) return peak;
  peak.pass = plan.passes[plan.order[peak.position].index].name;
  for (const PlannedResource& r : plan.resources)
    if (isTransient(r.kind) && !r.culled && r.memory.placed() && r.firstUse <= peak.position &&
        peak.position <= r.lastUse)
      peak.live.push_back({r.name, r.memory.size});
  std::stable_sort(peak.live.begin(), peak.live.end(), [](const auto& a, const auto& b) { return a.bytes > b.bytes; });
  return peak;
}

}  // namespace sg::graph
