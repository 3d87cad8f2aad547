#pragma once

#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/graph/sync_types.hpp>
#include <shadelgraph/graph/version_table.hpp>

#include <span>
#include <vector>

namespace sg::graph {

// `to` must run after `from` because of `resource`: read after write, write
// after write, or write after read. dstStages are the stages of `to` that wait.
struct Dependency {
  PassId from;
  PassId to;
  ResourceId resource;
  PipelineStage dstStages = PipelineStage::None;
};

// Dependencies grouped by `from` (compressed adjacency lists).
struct DependencyGraph {
  std::vector<Dependency> edges;
  std::vector<uint32_t> firstEdge;  // per pass, plus one: successors of p are edges[firstEdge[p] .. firstEdge[p + 1])
  std::vector<Dependency> scratch;  // buildDependencies()'s working memory, kept for the next call
  // True when buildDependencies() found every edge going from an earlier-declared
  // pass to a later one (the usual case: no sort, no cycle); false when unknown.
  bool forwardOnly = false;

  uint32_t passCount() const { return firstEdge.empty() ? 0 : static_cast<uint32_t>(firstEdge.size() - 1); }
  std::span<const Dependency> successors(PassId p) const {
    return {edges.data() + firstEdge[p.index], edges.data() + firstEdge[p.index + 1]};
  }
};

// Dependencies between passes that are not culled (all passes if `culled` is empty).
DependencyGraph buildDependencies(const RenderGraph& graph, const VersionTable& versions,
                                  const std::vector<bool>& culled = {});
// The same into `deps`, reusing its memory.
void buildDependencies(const RenderGraph& graph, const VersionTable& versions, const std::vector<bool>& culled,
                       DependencyGraph& deps);

}  // namespace sg::graph
