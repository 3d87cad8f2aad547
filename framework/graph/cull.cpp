#include <shadelgraph/graph/cull.hpp>

namespace sg::graph {

std::vector<bool> cullPasses(const RenderGraph& graph, const VersionTable& versions,
                             bool externalWritesAreSideEffects) {
  std::vector<bool> culled;
  cullPasses(graph, versions, externalWritesAreSideEffects, culled);
  return culled;
}

void cullPasses(const RenderGraph& graph, const VersionTable& versions, bool externalWritesAreSideEffects,
                std::vector<bool>& culled) {
  const uint32_t passCount = graph.passCount();
  culled.assign(passCount, true);
  std::vector<PassId> needed;
  needed.reserve(passCount);
  // Inline: it runs once per access of every kept pass.
  const auto keep = [&](PassId p) __attribute__((always_inline)) {
    if (p.valid() && culled[p.index]) {
      culled[p.index] = false;
      needed.push_back(p);
    }
  };

  const uint8_t rootWrites =
      externalWritesAreSideEffects ? kindBit(ResourceKind::Imported) | kindBit(ResourceKind::Persistent) : 0;
  for (uint32_t p = 0; p < passCount; ++p) {
    if (graph.pass(PassId{p}).sideEffect || (versions.passKinds[p].written & rootWrites) != 0) keep(PassId{p});
  }
  for (const ResourceHandle output : graph.outputs()) {
    if (graph.isValid(output.id)) keep(versions.producerOf(output.id, output.version));
  }

  // A kept pass needs the producer of each version it reads, and of the version
  // it writes over (the write may keep part of it: load ops, partial writes).
  while (!needed.empty()) {
    const PassId pass = needed.back();
    needed.pop_back();
    for (const ResourceAccess& a : graph.accessesOf(pass)) {
      if (graph.isValid(a.resource)) keep(versions.producerOf(a.resource, a.version));
    }
  }
}

}  // namespace sg::graph
