#pragma once
// Occlusion culling between the two halves of the depth pre-pass: "hi-z"
// reduces the depth of the draws visible last frame to the farthest depth
// per 16x16 tile, "occlusion-cull" tests every draw's bounding sphere against
// it. Draws are only ever culled behind depth this frame really has, so
// nothing visible is culled.
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/draw_culling.hpp>

namespace sg::passes {

struct OcclusionCullResult {
  graph::ResourceHandle commands;  // this frame's draw commands (instance count 0: culled)
  graph::ResourceHandle late;      // draws visible now that the depth does not hold yet
};

// `commands`: the persistent draw commands, holding last frame's visibility.
OcclusionCullResult addOcclusionCull(graph::RenderGraph& graph, const render::DrawCulling& culling,
                                     const glm::mat4& viewProjection, uint32_t width, uint32_t height,
                                     graph::ResourceHandle depth, graph::ResourceHandle commands);
gpu::ComputePipelineDesc hiZPipeline();
gpu::ComputePipelineDesc occlusionCullPipeline();

}  // namespace sg::passes
