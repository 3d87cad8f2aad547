#pragma once
// Debug views of decoupled shading, like the talk's slides: the virtual
// sheet's occupancy and the shade storage. (The detail-level view is a
// variant of composite.) Each draws a new image the tonemap pass then shows.
#include <glm/glm.hpp>

#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// The sheet region [originChunks, originChunks + sizeChunks) one pixel per chunk,
// marked chunks coloured by detail level.
graph::ResourceHandle addOccupancyView(graph::RenderGraph& graph, const DecoupledFrame& frame,
                                       glm::uvec2 originChunks, glm::uvec2 sizeChunks);
// The shade storage image, stretched over the output.
graph::ResourceHandle addSheetView(graph::RenderGraph& graph, const DecoupledFrame& frame);
// Their pipelines.
gpu::GraphicsPipelineDesc occupancyViewPipeline();
gpu::GraphicsPipelineDesc sheetViewPipeline();

}  // namespace sg::passes
