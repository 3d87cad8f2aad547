#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Storage for every marked chunk, from hashed partitions; overflow counted;
// the chunks that keep last frame's shading counted apart (async compute).
void addShadelAllocate(graph::RenderGraph& graph, DecoupledFrame& frame);
gpu::ComputePipelineDesc shadelAllocatePipeline();

}  // namespace sg::passes
