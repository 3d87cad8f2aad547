#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// The shade frame's work list (frames in flight): every stored chunk of this
// frame's remap table, per object, into shadeFrame.work and .args (the shade
// frame's own buffers), for layer-shade passes declared after composite.
// Async compute. shadeFrame.previousRemap must be invalid (nothing is reused).
void addShadeFrameWork(graph::RenderGraph& graph, DecoupledFrame& shadeFrame);

}  // namespace sg::passes
