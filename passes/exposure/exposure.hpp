#pragma once
#include <shadelgraph/graph/render_graph.hpp>

namespace sg::passes {

// Automatic exposure from the log-average luminance of `hdr` (async compute).
// Returns the exposure buffer it writes (16 bytes: logAverage, exposure, pixels).
graph::ResourceHandle addExposure(graph::RenderGraph& graph, graph::ResourceHandle hdr);

}  // namespace sg::passes
