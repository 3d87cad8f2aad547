#pragma once
#include <span>

#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Per-object work lists in one shared buffer and one VkDispatchIndirectCommand
// per object per material layer, and the list of chunks that keep their
// stored shading (shade-reuse copies them in kept layers' image pairs) with
// its dispatch after the objects' (async compute).
void addWorkAggregate(graph::RenderGraph& graph, DecoupledFrame& frame);
// Its two steps: the per-object offsets and arguments, then the work items.
gpu::ComputePipelineDesc workOffsetsPipeline();
gpu::ComputePipelineDesc workFillPipeline();
// What the fill step binds (bindDecoupled), for another pass running it.
std::span<const uint32_t> workFillBindings();

}  // namespace sg::passes
