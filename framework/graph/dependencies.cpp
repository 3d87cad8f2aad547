#include <shadelgraph/graph/dependencies.hpp>

#include <algorithm>

namespace sg::graph {
namespace {

// Calls edge(from, to, resource, dstStages) for every dependency of a kept pass.
template <class Edge>
void forEachDependency(const RenderGraph& graph, const VersionTable& versions, const std::vector<bool>& culled,
                       Edge&& edge) {
  const auto kept = [&](PassId p) { return p.valid() && (culled.empty() || !culled[p.index]); };
  for (uint32_t p = 0; p < graph.passCount(); ++p) {
    const PassId pass{p};
    if (!kept(pass)) continue;
    for (const ResourceAccess& a : graph.accessesOf(pass)) {
      const uint32_t slot = graph.isValid(a.resource) ? versions.slot(a.resource, a.version) : kInvalidIndex;
      if (slot == kInvalidIndex) continue;
      // Read after write, or write after write: after the version's producer.
      const PassId producer = versions.producer[slot];
      if (kept(producer) && producer != pass) edge(producer, pass, a);
      // Write after read: after everyone reading the version written over.
      if (!a.write) continue;
      for (const PassId reader : versions.readersOf(slot)) {
        if (kept(reader) && reader != pass) edge(reader, pass, a);
      }
    }
  }
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
  std::vector<Dependency>& found = deps.scratch;
  found.clear();
  found.reserve(graph.declaration().accesses.size());  // about one edge per read: a fresh compiler grows it once
  deps.firstEdge.assign(passCount + 1, 0);
  forEachDependency(graph, versions, culled, [&](PassId from, PassId to, const ResourceAccess& a) {
    found.push_back({from, to, a.resource, a.stages});
    ++deps.firstEdge[from.index + 1];
  });
  for (uint32_t p = 0; p < passCount; ++p) deps.firstEdge[p + 1] += deps.firstEdge[p];
  deps.edges.resize(found.size());
  for (const Dependency& e : found) deps.edges[deps.firstEdge[e.from.index]++] = e;
  std::copy_backward(deps.firstEdge.begin(), deps.firstEdge.end() - 1, deps.firstEdge.end());  // one memmove
  deps.firstEdge[0] = 0;
}

}  // namespace sg::graph
