#pragma once
// Shadow maps: one depth map per shadowed light that reaches a visible object,
// side by side in one atlas (render::shadowViews gives each light its slot and
// matrix, which the frame uniforms carry to the shading passes).
#include <vector>

#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

struct ShadowMapDraws {
  uint32_t light = 0;  // index into the frame's lights
  uint32_t slot = 0;   // column of the atlas
  std::vector<uint32_t> casters;  // draws (indices into the scene's draws) the light reaches
};

// The atlas (D32F, `slots` maps of render::kShadowMapResolution side by side),
// cleared to the far plane and holding `maps`' casters. `view`: the scene and frame uniforms.
graph::ResourceHandle addShadowMaps(graph::RenderGraph& graph, const render::SceneView& view,
                                    std::vector<ShadowMapDraws> maps, uint32_t slots);
gpu::GraphicsPipelineDesc shadowMapPipeline();

}  // namespace sg::passes
