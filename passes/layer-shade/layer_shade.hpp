#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/decoupled_frame.hpp>

namespace sg::passes {

// Shades the visible chunks: one indirect dispatch per object per layer, an
// 8x8 workgroup per chunk (async compute).
void addLayerShade(graph::RenderGraph& graph, render::DecoupledFrame& frame);

}  // namespace sg::passes
