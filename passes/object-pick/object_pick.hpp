#pragma once
// Which object is under one pixel: the frame's draws rasterized through that
// pixel into a 1x1 id target (nearest wins by depth), copied to a buffer the
// host reads. In a frame only while a pick is pending (plugin::kPickResource).
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

// Writes into `result` (a buffer of one uint) the scene instance + 1 of the
// nearest of `view`'s draws at pixel `pixel` (x right, y down) of a frame of
// `size` pixels, 0 when none covers it; alpha-mask objects not where their
// alpha test cuts them away. Returns the version it writes.
graph::ResourceHandle addObjectPick(graph::RenderGraph& graph, const render::SceneView& view, glm::uvec2 pixel,
                                    glm::uvec2 size, graph::ResourceHandle result);
gpu::GraphicsPipelineDesc objectPickPipeline();
// For alpha-mask draws: the alpha test, with the scene material as set 1.
gpu::GraphicsPipelineDesc objectPickAlphaTestPipeline(VkDescriptorSetLayout materialSet);

}  // namespace sg::passes
