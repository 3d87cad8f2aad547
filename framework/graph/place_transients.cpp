#include <shadelgraph/graph/place_transients.hpp>

#include <shadelgraph/graph/branchless.hpp>

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <type_traits>

namespace sg::graph {
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

// From this many transients on, free ranges are a block list with size-class
// bins (cost per placement flat in the heap's fragments); below, a sorted
// array walked whole costs less. Both place identically. Callgrind, synthetic
// graphs (about one transient per pass), whole compile, block list against
// walk: +5.9% at 100 transients, +3.0% at 200, even at 300, -4.3% at 500,
// -13% at 1000 (session 20, before the walk went by stretches; not measured
// again since).
constexpr std::size_t kBlockListFrom = 320;

// From which position a transient's memory may be taken over on `queue`
// (kInvalidIndex: never), and the waits that prove it.
uint32_t availableFrom(const TransientLifetime& t, QueueClass queue, const CrossQueueOrder* queues,
                       PipelineStage& waitStages) {
  if (t.queues == toMask(queue)) return t.lastUse + 1;  // its own queue: submission order (and the discard barrier)
  if (queues) return queues->availableFrom(t.lastUse, t.queues, queue, waitStages);
  return t.queues == toMask(queue) ? t.lastUse + 1 : kInvalidIndex;
}

// `previous` (indices into `transients`) by resource id, each once: an
// insertion sort, for the few there are (std::sort and std::unique cost more).
void inIdOrderOnce(std::vector<uint32_t>& previous, std::span<const TransientLifetime> transients) {
  std::size_t kept = 0;
  for (std::size_t i = 0; i < previous.size(); ++i) {
    const uint32_t p = previous[i];
    const uint32_t id = transients[p].id;
    std::size_t at = kept;
    for (; at > 0 && transients[previous[at - 1]].id > id; --at) previous[at] = previous[at - 1];
    if (at > 0 && previous[at - 1] == p) {  // already there: undo the shift
      for (; at < kept; ++at) previous[at] = previous[at + 1];
      continue;
    }
    previous[at] = p;
    ++kept;
  }
  previous.resize(kept);
}

// The sweep over the order with one kind of free ranges (Ranges: FreeRanges
// or LinearFreeRanges, kept per heap in `freeLists`).
template <class Ranges>
void sweep(std::span<const TransientLifetime> transients, std::span<const MemoryRequirements> requirements,
           bool enableAliasing, QueueMask used, const CrossQueueOrder* queues, MemoryPlan& plan,
           std::vector<Ranges>& freeLists) {
  constexpr bool kLinear = std::is_same_v<Ranges, LinearFreeRanges>;
  MemoryPlan::Scratch& scratch = plan.scratch;
  const std::vector<uint32_t>& byStart = scratch.byStart;
  const std::vector<uint32_t>& byEnd = scratch.byEnd;
  std::vector<uint64_t>& unaliasedSize = scratch.unaliasedSize;
  std::vector<std::pair<uint32_t, uint32_t>>& aliasPairs = scratch.aliasPairs;
  std::vector<uint32_t>& previous = scratch.previous;
  auto& allowances = scratch.allowances;
  std::vector<uint32_t>& firstAllowanceAt = scratch.firstAllowanceAt;
  // Positions are those of the order up to the last use of a transient: an
  // allowance from any later position could never serve a transient.
  const uint32_t positions = transients.empty() ? 0 : transients[byEnd.back()].lastUse + 1;
  firstAllowanceAt.assign(positions, kInvalidIndex);
  uint32_t allowedUpTo = 0;  // the positions whose allowances were given
  std::vector<uint32_t>& blocks = scratch.blocks;  // (the block list's handles)
  if constexpr (!kLinear) blocks.resize(transients.size());
  unaliasedSize.clear();
  aliasPairs.clear();
  allowances.clear();
  // Usually one previous occupant and one deferred allowance per transient at most: grown once, not by doubling.
  aliasPairs.reserve(2 * transients.size());
  allowances.reserve(transients.size());
  previous.reserve(16);
  std::size_t ended = 0;
  for (const uint32_t index : byStart) {
    const TransientLifetime& t = transients[index];
    // Give back the memory of transients whose last use is behind us, to the
    // queues they are over for now; the other queues get it as their waits come.
    // (Those ending before t's first use are the buckets of the positions before it: how many, the
    // counting sort left in bucketStarts; a bound known up front, not a lifetime loaded at each step.)
    const std::size_t endedBefore = t.firstUse == 0 ? 0 : scratch.bucketStarts[t.firstUse - 1];
    for (; ended < endedBefore; ++ended) {
      const uint32_t doneIndex = byEnd[ended];
      const TransientLifetime& done = transients[doneIndex];
      const MemoryPlacement& m = plan.placements[done.id];
      if (!plan.heaps[m.heap].aliasing) continue;
      QueueMask now = QueueMask::None;
      // Only the queues in use, lowest first (each bit of the mask is a queue index).
      for (auto bits = static_cast<uint32_t>(used); bits != 0; bits &= bits - 1) {
        const auto q = static_cast<QueueClass>(std::countr_zero(bits));
        PipelineStage unused = PipelineStage::None;
        const uint32_t from = availableFrom(done, q, queues, unused);
        if (from <= t.firstUse) {
          now |= toMask(q);
        } else if (from < positions) {
          allowances.push_back({firstAllowanceAt[from], doneIndex, toMask(q)});
          firstAllowanceAt[from] = static_cast<uint32_t>(allowances.size() - 1);
        }
      }
      if constexpr (kLinear) {
        freeLists[m.heap].release(m.offset, m.size, doneIndex, now);
      } else {
        freeLists[m.heap].release(blocks[doneIndex], doneIndex, now);
      }
    }
    // (Allowances commute: their order within a position does not matter.)
    for (; allowedUpTo <= t.firstUse; ++allowedUpTo) {
      for (uint32_t i = firstAllowanceAt[allowedUpTo]; i != kInvalidIndex; i = allowances[i].next) {
        const auto a = allowances[i];
        const MemoryPlacement& m = plan.placements[transients[a.index].id];
        if constexpr (kLinear) {
          freeLists[m.heap].allow(m.offset, m.size, a.index, a.queues);
        } else {
          freeLists[m.heap].allow(a.index, a.queues);
        }
      }
    }

    const MemoryRequirements& req = requirements[t.id];
    uint32_t heap = 0;
    for (; heap < plan.heaps.size(); ++heap) {
      const Heap& h = plan.heaps[heap];
      if (h.aliasing == enableAliasing && (h.memoryTypeBits & req.memoryTypeBits) != 0) break;
    }
    if (heap == plan.heaps.size()) {
      plan.heaps.push_back({req.memoryTypeBits, 0, 1, QueueMask::None, enableAliasing});
      if (freeLists.size() < plan.heaps.size()) freeLists.emplace_back();
      freeLists[heap].clear(used);
      // Room for about as many fragments as transients: grown once, not by doubling (a new PlanCompiler's).
      if constexpr (kLinear) freeLists[heap].reserve(transients.size());
      unaliasedSize.push_back(0);
    }
    Heap& h = plan.heaps[heap];
    previous.clear();
    // The queue taking the memory over: its first use's (unknown without `queues` if several use it).
    QueueMask taker = queueCount(t.queues) == 1 ? t.queues : QueueMask::None;
    if (queues) taker = toMask(queues->queueAt(t.firstUse));
    uint64_t offset = 0;
    if (!enableAliasing) {
      offset = alignUp(h.size, req.alignment);
    } else if constexpr (kLinear) {
      offset = freeLists[heap].allocate(req.size, req.alignment, taker, h.size, previous);
    } else {
      offset = freeLists[heap].allocate(req.size, req.alignment, taker, h.size, previous, blocks[index]);
    }
    h.size = std::max(h.size, offset + req.size);
    h.alignment = std::max(h.alignment, req.alignment);
    h.memoryTypeBits &= req.memoryTypeBits;
    h.queues |= t.queues;
    unaliasedSize[heap] = alignUp(unaliasedSize[heap], req.alignment) + req.size;
    plan.placements[t.id] = {heap, offset, req.size};

    if (previous.size() > 1) inIdOrderOnce(previous, transients);  // usually none or one
    for (const uint32_t p : previous) {
      const TransientLifetime& before = transients[p];
      if (before.queues != taker && queueCount(taker) == 1) {
        const auto q = static_cast<QueueClass>(std::countr_zero(static_cast<uint32_t>(taker)));
        availableFrom(before, q, queues, plan.takeOverWaits[t.id]);
      }
      aliasPairs.emplace_back(t.id, before.id);
      aliasPairs.emplace_back(before.id, t.id);
    }
  }
}

}  // namespace

MemoryPlan placeTransients(std::span<const PlannedResource> resources,
                           std::span<const MemoryRequirements> requirements, bool enableAliasing,
                           const CrossQueueOrder* queues) {
  MemoryPlan plan;
  placeTransients(resources, requirements, enableAliasing, plan, queues);
  return plan;
}

void placeTransients(std::span<const PlannedResource> resources, std::span<const MemoryRequirements> requirements,
                     bool enableAliasing, MemoryPlan& plan, const CrossQueueOrder* queues) {
  std::vector<TransientLifetime> transients;
  for (uint32_t r = 0; r < resources.size(); ++r) {
    const PlannedResource& resource = resources[r];
    if (!isTransient(resource.kind) || resource.culled) continue;
    transients.push_back({r, resource.firstUse, resource.lastUse, resource.desc.queues});
  }
  placeTransients(transients, static_cast<uint32_t>(resources.size()), requirements, enableAliasing, plan, queues);
}

void placeTransients(std::span<const TransientLifetime> transients, uint32_t resourceCount,
                     std::span<const MemoryRequirements> requirements, bool enableAliasing, MemoryPlan& plan,
                     const CrossQueueOrder* queues) {
  plan.placements.assign(resourceCount, MemoryPlacement{});
  plan.aliasesWith.assign(resourceCount, Range{});
  plan.takeOverWaits.assign(resourceCount, PipelineStage::None);
  plan.heaps.clear();
  plan.heapBytes = 0;
  plan.heapBytesWithoutAliasing = 0;
  MemoryPlan::Scratch& scratch = plan.scratch;

  uint32_t positions = 0;
  QueueMask used = QueueMask::None;  // only these queues take memory over
  for (const TransientLifetime& t : transients) {
    if (t.id >= requirements.size()) throw std::invalid_argument("placeTransients: missing memory requirements");
    positions = std::max(positions, t.lastUse + 1);
    used |= t.queues;
  }
  const auto sizeOf = [&](uint32_t index) { return requirements[transients[index].id].size; };
  // Transients by first use, larger first at the same position (the tie
  // broken by declaration: the input's order); and by last use.
  std::vector<uint32_t>& byStart = scratch.byStart;
  std::vector<uint32_t>& byEnd = scratch.byEnd;
  bucketBy(transients, positions, [](const TransientLifetime& t) { return t.firstUse; }, scratch.bucketStarts,
           byStart);
  // Each position's transients in order: at most two in practice (a pass
  // writes one or two new resources), put in order by a swap or not, without
  // a branch (whether they are already in order is anyone's guess); a sort
  // for more. (bucketBy() left the end of each position's transients in bucketStarts.)
  if (!byStart.empty()) {
    const auto before = [&](uint32_t a, uint32_t b) {
      return (sizeOf(a) > sizeOf(b)) | ((sizeOf(a) == sizeOf(b)) & (transients[a].id < transients[b].id));
    };
    const auto lastIndex = static_cast<uint32_t>(byStart.size() - 1);
    uint32_t begin = 0;
    for (uint32_t p = 0; p < positions; ++p) {
      const uint32_t end = scratch.bucketStarts[p];
      if (end - begin > 2) [[unlikely]] {
        std::sort(byStart.begin() + begin, byStart.begin() + end, before);
      } else {
        // (Past the last transient when there are fewer than two: the same ones written back.)
        const uint32_t i = std::min(begin, lastIndex), j = std::min(begin + 1, lastIndex);
        const uint32_t a = byStart[i], b = byStart[j];
        const bool swap = (end - begin == 2) & before(b, a);
        byStart[i] = choose(swap, b, a);
        byStart[j] = choose(swap, a, b);
      }
      begin = end;
    }
  }
  bucketBy(transients, positions, [](const TransientLifetime& t) { return t.lastUse; }, scratch.bucketStarts, byEnd);

  // (The free lists are kept for their memory; cleared when a heap reuses one.)
  if (transients.size() >= kBlockListFrom) {
    sweep(transients, requirements, enableAliasing, used, queues, plan, scratch.freeLists);
  } else {
    sweep(transients, requirements, enableAliasing, used, queues, plan, scratch.linearLists);
  }
  const std::vector<uint64_t>& unaliasedSize = scratch.unaliasedSize;
  const std::vector<std::pair<uint32_t, uint32_t>>& aliasPairs = scratch.aliasPairs;
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
