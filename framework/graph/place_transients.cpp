#include <shadelgraph/graph/place_transients.hpp>

#include <algorithm>
#include <stdexcept>

namespace sg::graph {
namespace {

uint64_t alignUp(uint64_t value, uint64_t alignment) {
  if (alignment <= 1) return value;
  if ((alignment & (alignment - 1)) == 0) return (value + alignment - 1) & ~(alignment - 1);  // Vulkan's case
  return (value + alignment - 1) / alignment * alignment;
}

// What placement needs of one used transient, packed for cache-friendly sorting.
struct Transient {
  uint32_t id;
  uint32_t firstUse;
  uint32_t lastUse;
  QueueMask queues;
  MemoryRequirements requirements;
};

// Free byte ranges of one aliasing heap, and who used each freed range last
// (that transient is what the next one placed there aliases with).
class FreeList {
 public:
  // Best fit: the smallest free range holding `size` bytes at `alignment`;
  // otherwise at the end of the heap (which grows). Appends the transients
  // that last used the range to `previous`.
  uint64_t allocate(uint64_t size, uint64_t alignment, uint64_t& heapSize, std::vector<uint32_t>& previous) {
    std::size_t best = blocks_.size();
    for (std::size_t i = 0; i < blocks_.size(); ++i) {
      const Block& b = blocks_[i];
      if (b.end - b.begin < size || alignUp(b.begin, alignment) + size > b.end) continue;
      if (best == blocks_.size() || b.end - b.begin < blocks_[best].end - blocks_[best].begin) best = i;
    }
    uint64_t offset = 0;
    if (best == blocks_.size()) {
      // Grow the heap, starting inside a free range that ends at its top.
      uint64_t start = heapSize;
      if (!blocks_.empty() && blocks_.back().end == heapSize) {
        start = blocks_.back().begin;
        blocks_.pop_back();
      }
      offset = alignUp(start, alignment);
      if (offset > start) blocks_.push_back({start, offset});
      heapSize = offset + size;
    } else {
      const Block b = blocks_[best];
      offset = alignUp(b.begin, alignment);
      auto at = blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(best));
      // What is left on either side stays free, in offset order.
      if (offset + size < b.end) at = blocks_.insert(at, {offset + size, b.end});
      if (b.begin < offset) blocks_.insert(at, {b.begin, offset});
    }
    takeOver(offset, offset + size, previous);
    return offset;
  }

  void release(uint64_t offset, uint64_t size, uint32_t occupant) {
    Block block{offset, offset + size};
    auto next = std::lower_bound(blocks_.begin(), blocks_.end(), block.begin,
                                 [](const Block& b, uint64_t o) { return b.begin < o; });
    auto at = std::lower_bound(lastUsers_.begin(), lastUsers_.end(), block.begin,
                               [](const LastUser& u, uint64_t o) { return u.begin < o; });
    lastUsers_.insert(at, {block.begin, block.end, occupant});
    if (next != blocks_.end() && next->begin == block.end) {
      block.end = next->end;
      next = blocks_.erase(next);
    }
    if (next != blocks_.begin() && std::prev(next)->end == block.begin) {
      std::prev(next)->end = block.end;
      return;
    }
    blocks_.insert(next, block);
  }

 private:
  struct Block {
    uint64_t begin;
    uint64_t end;
  };
  struct LastUser {
    uint64_t begin;
    uint64_t end;
    uint32_t occupant;
  };

  // [begin, end) is allocated again: report and forget its last users.
  void takeOver(uint64_t begin, uint64_t end, std::vector<uint32_t>& previous) {
    auto first = std::lower_bound(lastUsers_.begin(), lastUsers_.end(), begin,
                                  [](const LastUser& u, uint64_t o) { return u.end <= o; });
    auto last = first;
    while (last != lastUsers_.end() && last->begin < end) previous.push_back((last++)->occupant);
    if (first == last) return;
    LastUser rest[2];
    std::size_t count = 0;
    if (first->begin < begin) rest[count++] = {first->begin, begin, first->occupant};
    if (std::prev(last)->end > end) rest[count++] = {end, std::prev(last)->end, std::prev(last)->occupant};
    lastUsers_.insert(lastUsers_.erase(first, last), rest, rest + count);
  }

  std::vector<Block> blocks_;        // by offset, never adjacent
  std::vector<LastUser> lastUsers_;  // freed ranges by offset, not coalesced
};

}  // namespace

MemoryPlan placeTransients(std::span<const PlannedResource> resources,
                           std::span<const MemoryRequirements> requirements, bool enableAliasing) {
  MemoryPlan plan;
  placeTransients(resources, requirements, enableAliasing, plan);
  return plan;
}

void placeTransients(std::span<const PlannedResource> resources, std::span<const MemoryRequirements> requirements,
                     bool enableAliasing, MemoryPlan& plan) {
  const auto resourceCount = static_cast<uint32_t>(resources.size());
  plan.placements.assign(resourceCount, MemoryPlacement{});
  plan.aliasesWith.assign(resourceCount, Range{});
  plan.heaps.clear();
  plan.heapBytes = 0;
  plan.heapBytesWithoutAliasing = 0;

  std::vector<Transient> transients;  // by id
  uint32_t positions = 0;
  for (uint32_t r = 0; r < resourceCount; ++r) {
    const PlannedResource& resource = resources[r];
    if (!isTransient(resource.kind) || resource.culled) continue;
    if (r >= requirements.size()) throw std::invalid_argument("placeTransients: missing memory requirements");
    transients.push_back({r, resource.firstUse, resource.lastUse, resource.desc.queues, requirements[r]});
    positions = std::max(positions, resource.lastUse + 1);
  }
  // Transients by first use, larger first at the same position; and by last
  // use. Positions are dense, so both are counting sorts.
  const auto bucketBy = [&](auto position) {
    std::vector<uint32_t> first(positions + 1, 0);
    for (const Transient& t : transients) ++first[position(t) + 1];
    for (uint32_t p = 0; p < positions; ++p) first[p + 1] += first[p];
    std::vector<uint32_t> sorted(transients.size());
    for (uint32_t i = 0; i < transients.size(); ++i) sorted[first[position(transients[i])]++] = i;
    return sorted;
  };
  std::vector<uint32_t> byStart = bucketBy([](const Transient& t) { return t.firstUse; });
  const std::vector<uint32_t> byEnd = bucketBy([](const Transient& t) { return t.lastUse; });
  for (std::size_t begin = 0; begin < byStart.size();) {
    std::size_t end = begin + 1;
    while (end < byStart.size() && transients[byStart[end]].firstUse == transients[byStart[begin]].firstUse) ++end;
    if (end - begin > 1) {
      std::sort(byStart.begin() + static_cast<std::ptrdiff_t>(begin), byStart.begin() + static_cast<std::ptrdiff_t>(end),
                [&](uint32_t a, uint32_t b) {
                  return transients[a].requirements.size != transients[b].requirements.size
                             ? transients[a].requirements.size > transients[b].requirements.size
                             : a < b;
                });
    }
    begin = end;
  }

  std::vector<FreeList> freeLists;      // per heap (aliasing heaps only use theirs)
  std::vector<uint64_t> unaliasedSize;  // per heap: its size if nothing aliased
  std::vector<std::pair<uint32_t, uint32_t>> aliasPairs;
  std::vector<uint32_t> previous;
  std::size_t ended = 0;
  for (const uint32_t index : byStart) {
    const Transient& t = transients[index];
    // Give back the memory of transients whose last use is behind us.
    for (; ended < byEnd.size() && transients[byEnd[ended]].lastUse < t.firstUse; ++ended) {
      const Transient& done = transients[byEnd[ended]];
      const MemoryPlacement& m = plan.placements[done.id];
      if (plan.heaps[m.heap].aliasing) freeLists[m.heap].release(m.offset, m.size, done.id);
    }

    const MemoryRequirements& req = t.requirements;
    const bool aliases = enableAliasing && queueCount(t.queues) == 1;
    uint32_t heap = 0;
    for (; heap < plan.heaps.size(); ++heap) {
      const Heap& h = plan.heaps[heap];
      if (h.aliasing == aliases && (!aliases || h.queues == t.queues) &&
          (h.memoryTypeBits & req.memoryTypeBits) != 0) {
        break;
      }
    }
    if (heap == plan.heaps.size()) {
      plan.heaps.push_back({req.memoryTypeBits, 0, 1, QueueMask::None, aliases});
      freeLists.emplace_back();
      unaliasedSize.push_back(0);
    }
    Heap& h = plan.heaps[heap];
    previous.clear();
    const uint64_t offset =
        aliases ? freeLists[heap].allocate(req.size, req.alignment, h.size, previous) : alignUp(h.size, req.alignment);
    h.size = std::max(h.size, offset + req.size);
    h.alignment = std::max(h.alignment, req.alignment);
    h.memoryTypeBits &= req.memoryTypeBits;
    h.queues |= t.queues;
    unaliasedSize[heap] = alignUp(unaliasedSize[heap], req.alignment) + req.size;
    plan.placements[t.id] = {heap, offset, req.size};

    std::sort(previous.begin(), previous.end());
    previous.erase(std::unique(previous.begin(), previous.end()), previous.end());
    for (const uint32_t p : previous) {
      aliasPairs.emplace_back(t.id, p);
      aliasPairs.emplace_back(p, t.id);
    }
  }
  for (uint32_t heap = 0; heap < plan.heaps.size(); ++heap) {
    plan.heapBytes += plan.heaps[heap].size;
    plan.heapBytesWithoutAliasing += unaliasedSize[heap];
  }

  // Alias lists grouped by resource (counting sort of the pairs).
  for (const auto& [r, other] : aliasPairs) ++plan.aliasesWith[r].count;
  uint32_t first = 0;
  for (Range& range : plan.aliasesWith) {
    range.first = first;
    first += range.count;
    range.count = 0;
  }
  plan.aliases.resize(aliasPairs.size());
  for (const auto& [r, other] : aliasPairs) {
    Range& range = plan.aliasesWith[r];
    plan.aliases[range.first + range.count++] = ResourceId{other};
  }
}

}  // namespace sg::graph
