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

// Copies the chunks that keep their stored shading (work-aggregate's reuse
// list) from each of `layers`' last-frame image into its current one, at the
// same place (async compute; before the layers shade the rest). Only for kept
// layers: with stable allocation the shade storage keeps its chunks in place.
void addShadeReuse(graph::RenderGraph& graph, DecoupledFrame& frame, std::vector<KeptLayerImage>& layers);
// The copy for images of `format`.
gpu::ComputePipelineDesc shadeReusePipeline(graph::Format format = graph::Format::RGBA16F);

}  // namespace sg::passes
