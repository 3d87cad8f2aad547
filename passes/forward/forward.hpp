#pragma once
#include <glm/glm.hpp>

#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

struct ForwardTargets {
  graph::ResourceHandle color;
  graph::ResourceHandle depth;
};

// Opaque objects with their glTF material (graphics), against the z-prepass
// depth; clears the colour.
// `background`: the HDR colour where no object is (the analytic sky's horizon-ish blue, in cd/m^2).
ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                glm::vec3 background = {0.42f, 0.55f, 0.75f});

}  // namespace sg::passes
