#pragma once
#include <vector>

#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/depth_pass_draws.hpp>
#include <shadelgraph/render/scene_view.hpp>

#include "overdraw_probe.hpp"

namespace sg::passes {

// Depth of every opaque object (graphics), clearing it first, and of the
// `alphaTested` draws (decoupled alpha-mask objects: shadel-mark and composite
// test against their depth) where their alpha test keeps them; of those the
// frame's draw commands keep when the view has them (see readDrawCommands).
// Returns the depth version it writes. `counter`: counts the samples passing
// the depth test (a measurement frame, z_prepass_choice.hpp). `package`:
// draws another package adds, with their target (depth_pass_draws.hpp;
// package->target is updated to the version written).
graph::ResourceHandle addZPrepass(graph::RenderGraph& graph, const render::SceneView& view, graph::ResourceHandle depth,
                                  std::vector<uint32_t> alphaTested = {}, OverdrawCounter counter = {},
                                  render::DepthPassDraws* package = nullptr);
// Adds to the depth the opaque (and `alphaTested`) draws of `view` that `late`
// (indirect draw commands by draw index, from occlusion-cull) keeps.
graph::ResourceHandle addZPrepassLate(graph::RenderGraph& graph, const render::SceneView& view,
                                      graph::ResourceHandle depth, graph::ResourceHandle late,
                                      std::vector<uint32_t> alphaTested = {}, OverdrawCounter counter = {},
                                      render::DepthPassDraws* package = nullptr);
gpu::GraphicsPipelineDesc zPrepassPipeline();
// The z-prepass's own draws beside a package's (DepthPassDraws): they write 0 to its target.
gpu::GraphicsPipelineDesc zPrepassNoValuePipeline();
// The alpha-tested variant: the scene material is set 1.
gpu::GraphicsPipelineDesc zPrepassAlphaTestPipeline(VkDescriptorSetLayout materialSet);

}  // namespace sg::passes
