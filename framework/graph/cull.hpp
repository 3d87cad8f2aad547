#pragma once

#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/graph/version_table.hpp>

#include <vector>

namespace sg::graph {

// Which passes to drop because nobody needs their results: culled[p] is true
// for a dropped pass. Kept are side-effect passes, producers of outputs, (if
// `externalWritesAreSideEffects`) writers of imported and persistent resources,
// and, transitively, the producers of every version a kept pass reads or
// writes over. Linear in the number of accesses.
std::vector<bool> cullPasses(const RenderGraph& graph, const VersionTable& versions,
                             bool externalWritesAreSideEffects = true);
// The same into `culled`, reusing its memory.
void cullPasses(const RenderGraph& graph, const VersionTable& versions, bool externalWritesAreSideEffects,
                std::vector<bool>& culled);

}  // namespace sg::graph
