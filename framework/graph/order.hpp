#pragma once

#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/handles.hpp>

#include <vector>

namespace sg::graph {

// Topological order of the kept passes (Kahn's algorithm). Among passes that
// are ready, the one declared first goes first, so the order is deterministic
// and follows declaration order wherever dependencies allow. The ready set is
// a two-level bitset: O(V + E), plus a word scan per 4096 passes. When every
// dependency points forward in declaration order (the usual case), the sort is
// skipped: declaration order is already the answer.
// Passes on a cycle (which validate() reports) are left out. Dependencies
// touching a culled pass are ignored, so `deps` may cover all passes.
std::vector<PassId> orderPasses(const DependencyGraph& deps, const std::vector<bool>& culled = {});
// The same into `order`, reusing its memory.
void orderPasses(const DependencyGraph& deps, const std::vector<bool>& culled, std::vector<PassId>& order);

}  // namespace sg::graph
