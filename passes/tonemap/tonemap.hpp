#pragma once
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>

namespace sg::passes {

// HDR -> the 8-bit sRGB output, exposed by the exposure pass's result
// (graphics). passthrough: copy the colours unchanged (debug views).
graph::ResourceHandle addTonemap(graph::RenderGraph& graph, graph::ResourceHandle hdr, graph::ResourceHandle exposure,
                                 graph::ResourceHandle output, bool passthrough = false);
gpu::GraphicsPipelineDesc tonemapPipeline(VkFormat output, bool passthrough);

}  // namespace sg::passes
