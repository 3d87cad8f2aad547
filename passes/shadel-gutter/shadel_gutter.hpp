#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Fills the one-shadel gutter of every stored chunk's tile in the composited
// layer (frame.shadedColor) from its neighbouring chunks, after the layers
// and the reuse copy wrote it, so composite reads a level's footprint from
// one tile (async compute).
void addShadelGutter(graph::RenderGraph& graph, DecoupledFrame& frame);
gpu::ComputePipelineDesc shadelGutterPipeline();

}  // namespace sg::passes
