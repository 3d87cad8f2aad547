#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Rasterizes the decoupled objects against the z-prepass depth (early test,
// no colour) and marks the chunks of the shadels composite will read.
void addShadelMark(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle depth);
gpu::GraphicsPipelineDesc shadelMarkPipeline();

}  // namespace sg::passes
