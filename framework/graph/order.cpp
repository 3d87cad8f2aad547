#include <shadelgraph/graph/order.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>

namespace sg::graph {
namespace {

// Passes ready to run, as a two-level bitset: the smallest (first declared)
// is found with two count-trailing-zeros instead of a heap's log n steps.
class ReadySet {
 public:
  explicit ReadySet(uint32_t size) : words_((size + 63) / 64, 0), summary_((words_.size() + 63) / 64, 0) {}

  void insert(uint32_t p) {
    words_[p / 64] |= uint64_t{1} << (p % 64);
    summary_[p / 4096] |= uint64_t{1} << ((p / 64) % 64);
  }
  // Removes the smallest pass into `p`; false when none is ready.
  bool popSmallest(uint32_t& p) {
    std::size_t s = 0;
    while (s < summary_.size() && summary_[s] == 0) ++s;  // one word per 4096 passes
    if (s == summary_.size()) return false;
    const std::size_t w = s * 64 + static_cast<std::size_t>(std::countr_zero(summary_[s]));
    const uint32_t bit = static_cast<uint32_t>(std::countr_zero(words_[w]));
    words_[w] &= words_[w] - 1;
    if (words_[w] == 0) summary_[s] &= summary_[s] - 1;
    p = static_cast<uint32_t>(w * 64 + bit);
    return true;
  }

 private:
  std::vector<uint64_t> words_;
  std::vector<uint64_t> summary_;  // bit w set: words_[w] != 0
};

}  // namespace

std::vector<PassId> orderPasses(const DependencyGraph& deps, const std::vector<bool>& culled) {
  std::vector<PassId> order;
  orderPasses(deps, culled, order);
  return order;
}

void orderPasses(const DependencyGraph& deps, const std::vector<bool>& culled, std::vector<PassId>& order) {
  const uint32_t passCount = deps.passCount();
  const auto kept = [&](PassId p) { return culled.empty() || !culled[p.index]; };
  order.clear();
  order.reserve(passCount);
  // The usual case: every pass declared after the passes it depends on. Then
  // declaration order is the answer (each pass is ready when its turn comes).
  if (deps.forwardOnly ||
      std::all_of(deps.edges.begin(), deps.edges.end(), [](const Dependency& e) { return e.from < e.to; })) {
    for (uint32_t p = 0; p < passCount; ++p) {
      if (kept(PassId{p})) order.push_back(PassId{p});
    }
    return;
  }
  std::vector<uint32_t> waitingFor(passCount, 0);
  for (const Dependency& e : deps.edges) {
    if (kept(e.from) && kept(e.to)) ++waitingFor[e.to.index];
  }

  ReadySet ready(passCount);
  for (uint32_t p = 0; p < passCount; ++p) {
    if (kept(PassId{p}) && waitingFor[p] == 0) ready.insert(p);
  }
  uint32_t next = 0;
  while (ready.popSmallest(next)) {
    const PassId pass{next};
    order.push_back(pass);
    for (const Dependency& e : deps.successors(pass)) {
      if (kept(e.to) && --waitingFor[e.to.index] == 0) ready.insert(e.to.index);
    }
  }
}

}  // namespace sg::graph
