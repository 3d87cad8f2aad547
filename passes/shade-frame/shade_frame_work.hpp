#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// The shade frame's work list (frames in flight): every stored chunk of this
// frame's remap table, per object, into shadeFrame.work and .args (the shade
// frame's own buffers), for layer-shade passes declared after composite.
// Async compute; it writes the same shade storage, at the same chunk slots, as its raster frame.
void addShadeFrameWork(graph::RenderGraph& graph, DecoupledFrame& shadeFrame);
// Its steps: 0 zeroes the list's counters, 1 counts each object's stored
// chunks; then work-offsets and shadeFrameFillPipeline (work-fill, nothing reused).
gpu::ComputePipelineDesc shadeFramePhasePipeline(int phase);
gpu::ComputePipelineDesc shadeFrameFillPipeline();

}  // namespace sg::passes
