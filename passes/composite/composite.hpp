#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Draws the decoupled objects with their shaded samples (manual trilinear
// through the remap table) over the forward pass's colour. Returns the colour.
graph::ResourceHandle addComposite(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle color,
                                   graph::ResourceHandle depth);
// filter: 0 point, 1 bilinear, 2 trilinear; levelView shows the detail level
// instead; alphaTest: the variant for alpha-mask objects, `materialSet` (the
// scene material) its set 1.
gpu::GraphicsPipelineDesc compositePipeline(int filter, bool levelView, bool alphaTest = false,
                                            VkDescriptorSetLayout materialSet = VK_NULL_HANDLE);

}  // namespace sg::passes
