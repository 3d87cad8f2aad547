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
// The same without a depth pre-pass: clears colour and depth and writes the
// depth as it shades (the draws the frame's draw commands keep, when culled).
ForwardTargets addForwardOpaqueWritingDepth(graph::RenderGraph& graph, const render::SceneView& view,
                                            ForwardTargets targets);
// Adds the draws `late` keeps (indirect commands by draw index, from
// occlusion-cull) to colour and depth: the draws the first half did not know were visible.
ForwardTargets addForwardOpaqueLate(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                    graph::ResourceHandle late);

}  // namespace sg::passes
