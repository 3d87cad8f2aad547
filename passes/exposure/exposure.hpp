#pragma once
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>

namespace sg::passes {

// Automatic exposure from the log-average luminance of `hdr` (async compute).
// Returns the exposure buffer it writes (shader::SgExposure).
graph::ResourceHandle addExposure(graph::RenderGraph& graph, graph::ResourceHandle hdr);
gpu::ComputePipelineDesc exposurePipeline();

}  // namespace sg::passes
