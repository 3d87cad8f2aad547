#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

struct ForwardTargets {
  graph::ResourceHandle color;
  graph::ResourceHandle depth;
};

// Opaque and alpha-masked objects with their glTF material (graphics). Opaque
// depth comes from the z-prepass; masked objects write their own depth.
ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets);

// Alpha-blended objects, sorted back to front, over the opaque result with
// depth test and no depth write. Only added when the scene has such materials.
graph::ResourceHandle addForwardBlend(graph::RenderGraph& graph, const render::SceneView& view,
                                      const glm::vec3& cameraPosition, ForwardTargets targets);

}  // namespace sg::passes
