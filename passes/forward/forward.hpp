#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

struct ForwardTargets {
  graph::ResourceHandle color;
  graph::ResourceHandle depth;
};

// Opaque objects with their glTF material (graphics), against the z-prepass
// depth; clears the colour.
ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets);

}  // namespace sg::passes
