#pragma once
#include <optional>
#include <span>

#include <glm/glm.hpp>

#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>

#include "z-prepass/overdraw_probe.hpp"

namespace sg::passes {

struct ForwardTargets {
  graph::ResourceHandle color;
  graph::ResourceHandle depth;
};

// The HDR colour where no object is: the analytic sky's horizon-ish blue,
// brightened with it (render::skyScale; a sunlit sky is thousands of cd/m^2).
glm::vec3 hdrBackground(std::span<const scene::Light> lights);
// scene.hdr's first write clears it to `background`: the colour is created
// unwritten (version 0) when forward-opaque has nothing to draw, and then the
// first pass writing it (alpha-mask, composite) clears instead of loading.
// Empty: the colour has content, load it.
std::optional<VkClearColorValue> clearIfUnwritten(graph::ResourceHandle color, glm::vec3 background);

// Opaque objects with their glTF material (graphics); clears the colour.
// Against the z-prepass depth; or, when no pass wrote targets.depth yet (no
// z-prepass), writing the depth themselves (cleared first, tested
// LESS_OR_EQUAL), so a pixel is shaded once per surface nearest when drawn.
// `counter`: counts the fragments shaded (a z-prepass measurement frame).
ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                glm::vec3 background, OverdrawCounter counter = {});
// Without a z-prepass, after occlusion-cull: adds to colour and depth the
// opaque draws of `view` that `late` (indirect draw commands by draw index)
// keeps, the draws found visible that the first half did not draw.
ForwardTargets addForwardOpaqueLate(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                    graph::ResourceHandle late);

}  // namespace sg::passes
