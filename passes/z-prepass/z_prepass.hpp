#pragma once
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

// Depth of every opaque object (graphics), clearing it first; of those the
// frame's draw commands keep when the view has them (see readDrawCommands).
// Returns the depth version it writes.
graph::ResourceHandle addZPrepass(graph::RenderGraph& graph, const render::SceneView& view, graph::ResourceHandle depth);
// Adds to the depth the opaque draws of `view` that `late` (indirect draw
// commands by draw index, from occlusion-cull) keeps.
graph::ResourceHandle addZPrepassLate(graph::RenderGraph& graph, const render::SceneView& view,
                                      graph::ResourceHandle depth, graph::ResourceHandle late);
gpu::GraphicsPipelineDesc zPrepassPipeline();

}  // namespace sg::passes
