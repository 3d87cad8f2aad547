#pragma once
#include <glm/glm.hpp>

#include <shadelgraph/graph/render_graph.hpp>

#include "forward/forward.hpp"

namespace sg::passes {

// Alpha-blended objects, sorted back to front, over the opaque result with
// depth test and no depth write. Only added when the scene has such materials.
graph::ResourceHandle addAlphaBlend(graph::RenderGraph& graph, const render::SceneView& view,
                                    const glm::vec3& cameraPosition, ForwardTargets targets);

}  // namespace sg::passes
