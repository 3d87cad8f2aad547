#pragma once
// Shadow maps: the maps of each shadowed light that reaches a visible object
// (a spot's one, a point light's six cube faces, a sun's cascades) in one
// atlas, kShadowAtlasColumns maps a row (render::shadowViews gives each map its
// slot and matrix, which the frame uniforms carry to the shading passes).
#include <vector>

#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

struct ShadowMapDraws {
  uint32_t slot = 0;  // the map's place in the atlas (its matrix: the frame uniforms' shadowMatrices[slot])
  std::vector<uint32_t> casters;  // draws (indices into the scene's draws) inside the map's view that its light reaches
};

// The atlas (D32F, `slots` maps of render::kShadowMapResolution, kShadowAtlasColumns
// a row), cleared to the far plane and holding `maps`' casters. `view`: the scene and frame uniforms.
graph::ResourceHandle addShadowMaps(graph::RenderGraph& graph, const render::SceneView& view,
                                    std::vector<ShadowMapDraws> maps, uint32_t slots);
gpu::GraphicsPipelineDesc shadowMapPipeline();

}  // namespace sg::passes
