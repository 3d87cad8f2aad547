#pragma once

#include <shadelgraph/graph/compile_options.hpp>
#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/graph_error.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/graph/version_table.hpp>

#include <vector>

namespace sg::graph {

// Every problem in the declaration, in a deterministic order (resources, then
// passes in declaration order, then branching writes, then a cycle). Empty
// means compile() can proceed. `options` supplies the output extent that
// relative image sizes resolve against.
std::vector<ValidationError> validate(const RenderGraph& graph, const CompileOptions& options = {});
// With the index and the dependencies of all passes already built (compile() reuses them).
std::vector<ValidationError> validate(const RenderGraph& graph, const VersionTable& versions,
                                      const DependencyGraph& allPasses, const CompileOptions& options);

}  // namespace sg::graph
