#pragma once
#include <vector>

#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// A layer image kept across frames (a view-independent layer's): reused
// chunks are copied in it too, so that every stored chunk holds its value.
struct KeptLayerImage {
  graph::ResourceHandle history;  // last frame's image
  graph::ResourceHandle current;  // this frame's; replaced by the version the copy writes
  graph::Format format = graph::Format::RGBA16F;
};

// Copies the chunks that keep last frame's shading (work-aggregate's reuse
// list) from frame.previousShaded into frame.shadedColor at their new
// addresses, and likewise in each of `layers` (async compute; before the
// layers shade the rest).
void addShadeReuse(graph::RenderGraph& graph, DecoupledFrame& frame, std::vector<KeptLayerImage>& layers);
// The copy for images of `format`.
gpu::ComputePipelineDesc shadeReusePipeline(graph::Format format = graph::Format::RGBA16F);

}  // namespace sg::passes
