#pragma once
#include <shadelgraph/graph/render_graph.hpp>

#include <optional>

#include "forward/forward.hpp"

namespace sg::passes {

// Alpha-masked objects (discard below the cutoff), writing their own depth
// over the opaque result. Only added when the scene has such materials.
// `clear`: the colour is still unwritten (clearIfUnwritten), clear it first.
ForwardTargets addAlphaMask(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                            std::optional<VkClearColorValue> clear = {});

}  // namespace sg::passes
