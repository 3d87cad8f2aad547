#pragma once
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

// Depth of every opaque object (graphics). Returns the depth version it writes.
graph::ResourceHandle addZPrepass(graph::RenderGraph& graph, const render::SceneView& view, graph::ResourceHandle depth);
gpu::GraphicsPipelineDesc zPrepassPipeline();

}  // namespace sg::passes
