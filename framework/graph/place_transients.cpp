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

}  // namespace

namespace detail {

uint64_t FreeList::allocate(uint64_t size, uint64_t alignment, uint64_t& heapSize, std::vector<uint32_t>& previous) {
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

void FreeList::release(uint64_t offset, uint64_t size, uint32_t occupant) {
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

// [begin, end) is allocated again: report and forget its last users.
void FreeList::takeOver(uint64_t begin, uint64_t end, std::vector<uint32_t>& previous) {
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

}  // namespace detail

namespace {

// Indices of `transients` sorted by a position (first or last use): positions
// are dense, so a counting sort. `starts` is scratch.
template <class Position>
void bucketBy(std::span<const TransientLifetime> transients, uint32_t positions, Position position,
              std::vector<uint32_t>& starts, std::vector<uint32_t>& sorted) {
  starts.assign(positions + 1, 0);
  for (const TransientLifetime& t : transients) ++starts[position(t) + 1];
  for (uint32_t p = 0; p < positions; ++p) starts[p + 1] += starts[p];
  sorted.resize(transients.size());
  for (uint32_t i = 0; i < transients.size(); ++i) sorted[starts[position(transients[i])]++] = i;
}

}  // namespace

MemoryPlan placeTransients(std::span<const PlannedResource> resources,
                           std::span<const MemoryRequirements> requirements, bool enableAliasing) {
  MemoryPlan plan;
  placeTransients(resources, requirements, enableAliasing, plan);
  return plan;
}

void placeTransients(std::span<const PlannedResource> resources, std::span<const MemoryRequirements> requirements,
                     bool enableAliasing, MemoryPlan& plan) {
  std::vector<TransientLifetime> transients;
  for (uint32_t r = 0; r < resources.size(); ++r) {
    const PlannedResource& resource = resources[r];
    if (!isTransient(resource.kind) || resource.culled) continue;
    transients.push_back({r, resource.firstUse, resource.lastUse, resource.desc.queues});
  }
  placeTransients(transients, static_cast<uint32_t>(resources.size()), requirements, enableAliasing, plan);
}

void placeTransients(std::span<const TransientLifetime> transients, uint32_t resourceCount,
                     std::span<const MemoryRequirements> requirements, bool enableAliasing, MemoryPlan& plan) {
  plan.placements.assign(resourceCount, MemoryPlacement{});
  plan.aliasesWith.assign(resourceCount, Range{});
  plan.heaps.clear();
  plan.heapBytes = 0;
  plan.heapBytesWithoutAliasing = 0;
  MemoryPlan::Scratch& scratch = plan.scratch;

  uint32_t positions = 0;
  for (const TransientLifetime& t : transients) {
    if (t.id >= requirements.size()) throw std::invalid_argument("placeTransients: missing memory requirements");
    positions = std::max(positions, t.lastUse + 1);
  }
  const auto sizeOf = [&](uint32_t index) { return requirements[transients[index].id].size; };
  // Transients by first use, larger first at the same position (the tie
  // broken by declaration: the input's order); and by last use.
  std::vector<uint32_t>& byStart = scratch.byStart;
  std::vector<uint32_t>& byEnd = scratch.byEnd;
  bucketBy(transients, positions, [](const TransientLifetime& t) { return t.firstUse; }, scratch.bucketStarts,
           byStart);
  bucketBy(transients, positions, [](const TransientLifetime& t) { return t.lastUse; }, scratch.bucketStarts, byEnd);
  for (std::size_t begin = 0; begin < byStart.size();) {
    std::size_t end = begin + 1;
    while (end < byStart.size() && transients[byStart[end]].firstUse == transients[byStart[begin]].firstUse) ++end;
    if (end - begin > 1) {
      std::sort(byStart.begin() + static_cast<std::ptrdiff_t>(begin), byStart.begin() + static_cast<std::ptrdiff_t>(end),
                [&](uint32_t a, uint32_t b) {
                  return sizeOf(a) != sizeOf(b) ? sizeOf(a) > sizeOf(b) : transients[a].id < transients[b].id;
                });
    }
    begin = end;
  }

  std::vector<detail::FreeList>& freeLists = scratch.freeLists;  // kept for their memory; cleared when a heap reuses one
  std::vector<uint64_t>& unaliasedSize = scratch.unaliasedSize;
  std::vector<std::pair<uint32_t, uint32_t>>& aliasPairs = scratch.aliasPairs;
  std::vector<uint32_t>& previous = scratch.previous;
  unaliasedSize.clear();
  aliasPairs.clear();
  std::size_t ended = 0;
  for (const uint32_t index : byStart) {
    const TransientLifetime& t = transients[index];
    // Give back the memory of transients whose last use is behind us.
    for (; ended < byEnd.size() && transients[byEnd[ended]].lastUse < t.firstUse; ++ended) {
      const TransientLifetime& done = transients[byEnd[ended]];
      const MemoryPlacement& m = plan.placements[done.id];
      if (plan.heaps[m.heap].aliasing) freeLists[m.heap].release(m.offset, m.size, done.id);
    }

    const MemoryRequirements& req = requirements[t.id];
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
      if (freeLists.size() < plan.heaps.size()) freeLists.emplace_back();
      freeLists[heap].clear();
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
