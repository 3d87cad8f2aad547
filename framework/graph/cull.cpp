#include <shadelgraph/graph/cull.hpp>

#include <algorithm>

namespace sg::graph {
namespace {

// The general case: a worklist from the roots, following producers.
void keepNeededByWorklist(const RenderGraph& graph, const VersionTable& versions, std::vector<uint8_t>& needed) {
  const uint32_t passCount = graph.passCount();
  std::vector<PassId> work;
  work.reserve(passCount);
  for (uint32_t p = 0; p < passCount; ++p) {
    if (needed[p]) work.push_back(PassId{p});
  }
  while (!work.empty()) {
    const PassId pass = work.back();
    work.pop_back();
    for (const ResourceAccess& a : graph.accessesOf(pass)) {
      if (!graph.isValid(a.resource)) continue;
      const PassId producer = versions.producerOf(a.resource, a.version);
      if (producer.valid() && !needed[producer.index]) {
        needed[producer.index] = 1;
        work.push_back(producer);
      }
    }
  }
}

}  // namespace

std::vector<bool> cullPasses(const RenderGraph& graph, const VersionTable& versions,
                             bool externalWritesAreSideEffects) {
  std::vector<bool> culled;
  cullPasses(graph, versions, externalWritesAreSideEffects, culled);
  return culled;
}

void cullPasses(const RenderGraph& graph, const VersionTable& versions, bool externalWritesAreSideEffects,
                std::vector<bool>& culled) {
  const uint32_t passCount = graph.passCount();
  const uint32_t resourceCount = graph.resourceCount();
  // needed[p] != 0: pass p is kept; needed[passCount] takes the marks meant
  // for "no producer" (min(kInvalidIndex, passCount)), so that marking needs no test.
  std::vector<uint8_t> needed(passCount + 1, 0);
  const uint8_t rootWrites =
      externalWritesAreSideEffects ? kindBit(ResourceKind::Imported) | kindBit(ResourceKind::Persistent) : 0;
  for (uint32_t p = 0; p < passCount; ++p) {
    needed[p] = graph.pass(PassId{p}).sideEffect | ((versions.passKinds[p].written & rootWrites) != 0);
  }
  for (const ResourceHandle output : graph.outputs()) {
    if (graph.isValid(output.id)) needed[std::min(versions.producerOf(output.id, output.version).index, passCount)] = 1;
  }

  // A kept pass needs the producer of each version it reads, and of the version
  // it writes over (the write may keep part of it: load ops, partial writes).
  // The usual case: every producer is declared before the passes using its
  // versions, so one sweep from the last pass's accesses to the first's sees
  // each pass after everything that needs it. Every access marks its
  // producer with its pass's own mark (no test per access whose outcome
  // varies at random); a producer declared later than its user (seen too
  // early) sends the walk to the worklist, which handles any order.
  const uint32_t* firstSlot = versions.firstSlot.data();
  const PassId* producers = versions.producer.data();
  uint8_t* mark = needed.data();
  bool producerLater = false;
  forEachAccessInReverse(graph, versions, [&](uint32_t p, const ResourceAccess& a) __attribute__((always_inline)) {
    const uint32_t r = a.resource.index;
    if (r >= resourceCount) [[unlikely]] return;  // !graph.isValid(a.resource)
    const uint32_t first = firstSlot[r];
    const bool known = a.version < firstSlot[r + 1] - first;  // else a forged version: no producer
    // An unknown version reads version 0's slot, which has no producer.
    const uint32_t index = producers[first + (known ? a.version : 0u)].index;
    const uint32_t producer = index < passCount ? index : passCount;  // (std::min makes a branch here)
    const uint8_t keep = mark[p];
    producerLater |= (producer > p) & (producer < passCount) & (keep != 0);
    mark[producer] |= keep;
  });
  if (producerLater) [[unlikely]] keepNeededByWorklist(graph, versions, needed);

  culled.assign(passCount, false);
  for (uint32_t p = 0; p < passCount; ++p) culled[p] = needed[p] == 0;
}

}  // namespace sg::graph
