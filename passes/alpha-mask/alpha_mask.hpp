#pragma once
#include <shadelgraph/graph/render_graph.hpp>

#include "forward/forward.hpp"

namespace sg::passes {

// Alpha-masked objects (discard below the cutoff), writing their own depth
// over the opaque result. Only added when the scene has such materials.
ForwardTargets addAlphaMask(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets);

}  // namespace sg::passes
