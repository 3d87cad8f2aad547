#include <shadelgraph/graph/dependencies.hpp>

#include <algorithm>

namespace sg::graph {
namespace {

// Lists every dependency of a kept pass in found[0 .. returned count), in `to`
// order, and counts each source's edges in firstEdge[source + 1]. Whether an
// access makes an edge depends on the graph at random (a write over version 0
// has no producer; a version a pass wrote itself is no dependency), so every
// candidate is written and only a real edge advances the list and its
// source's count: no branch per candidate. `everyPassKept`: `culled` is empty.
template <bool everyPassKept>
uint32_t listDependencies(const RenderGraph& graph, const VersionTable& versions, const std::vector<bool>& culled,
                          std::vector<Dependency>& found, std::vector<uint32_t>& firstEdge, bool& backward) {
  const uint32_t resourceCount = graph.resourceCount();
  // Raw pointers in locals: the walk stores through uint32_t pointers, and
  // `found` only grows out of line, so these stay in registers.
  const uint32_t* firstSlot = versions.firstSlot.data();
  const PassId* producers = versions.producer.data();
  const uint32_t* firstReader = versions.firstReader.data();
  const PassId* readers = versions.readers.data();
  uint32_t* edgesFrom = firstEdge.data();  // [source + 1]; an invalid source's (+0) lands in [0] (uint32_t wraps)
  Dependency* list = found.data();
  uint32_t capacity = static_cast<uint32_t>(found.size());
  uint32_t count = 0;
  bool anyBackward = false;
  forEachAccess(graph, versions, [&](uint32_t p, const ResourceAccess& a) __attribute__((always_inline)) {
    if (!everyPassKept && culled[p]) return;
    const uint32_t r = a.resource.index;
    if (r >= resourceCount) [[unlikely]] return;  // !graph.isValid(a.resource)
    if (a.version >= firstSlot[r + 1] - firstSlot[r]) [[unlikely]] return;  // a forged version
    const uint32_t slot = firstSlot[r] + a.version;
    // Read after write, or write after write: after the version's producer.
    // Write after read (writes only): after everyone reading the version written over.
    const uint32_t firstReaderOfSlot = firstReader[slot];
    const uint32_t readerCount = (firstReader[slot + 1] - firstReaderOfSlot) & (a.write ? ~0u : 0u);
    if (count + 1 + readerCount > capacity) [[unlikely]] {
      found.resize(2 * (count + 1 + readerCount));
      list = found.data();
      capacity = static_cast<uint32_t>(found.size());
    }
    const PassId pass{p};
    const ResourceId resource = a.resource;
    const PipelineStage stages = a.stages;
    const auto add = [&](PassId from) __attribute__((always_inline)) {
      bool edge = from.valid() & (from != pass);
      if constexpr (!everyPassKept) edge = edge && !culled[from.index];
      // Field by field: a whole-struct copy goes through the stack here.
      Dependency& candidate = list[count];
      candidate.from = from;
      candidate.to = pass;
      candidate.resource = resource;
      candidate.dstStages = stages;
      count += edge;
      edgesFrom[from.index + 1] += edge;
      anyBackward |= edge & (from.index > p);
    };
    add(producers[slot]);
    for (uint32_t i = 0; i < readerCount; ++i) add(readers[firstReaderOfSlot + i]);
  });
  backward = anyBackward;
  return count;
}

}  // namespace

DependencyGraph buildDependencies(const RenderGraph& graph, const VersionTable& versions,
                                  const std::vector<bool>& culled) {
  DependencyGraph deps;
  buildDependencies(graph, versions, culled, deps);
  return deps;
}

void buildDependencies(const RenderGraph& graph, const VersionTable& versions, const std::vector<bool>& culled,
                       DependencyGraph& deps) {
  // One walk over the accesses (in `to` order), then a stable counting sort of
  // the edges by source: grouped by source, each source's in declaration order.
  const uint32_t passCount = graph.passCount();
  std::vector<Dependency>& found = deps.scratch;  // the first `count` entries are the edges found
  // Room for every candidate at once: one per access, plus one per reader of
  // each version written over, which is each read at most once unless two
  // writes go over one version (an error; the walk grows the list then).
  // Growing from empty instead reallocated and copied about eight times.
  const std::size_t candidates = graph.declaration().accesses.size() + versions.readers.size() + 1;
  if (found.size() < candidates) found.resize(candidates);
  deps.firstEdge.assign(passCount + 1, 0);
  bool backward = false;
  const uint32_t count = culled.empty() ? listDependencies<true>(graph, versions, culled, found, deps.firstEdge, backward)
                                        : listDependencies<false>(graph, versions, culled, found, deps.firstEdge, backward);
  deps.firstEdge[0] = 0;  // (the invalid sources' zeros)
  for (uint32_t p = 0; p < passCount; ++p) deps.firstEdge[p + 1] += deps.firstEdge[p];
  deps.edges.resize(count);
  for (uint32_t i = 0; i < count; ++i) deps.edges[deps.firstEdge[found[i].from.index]++] = found[i];
  std::copy_backward(deps.firstEdge.begin(), deps.firstEdge.end() - 1, deps.firstEdge.end());  // one memmove
  deps.firstEdge[0] = 0;
  deps.forwardOnly = !backward;
}

}  // namespace sg::graph
