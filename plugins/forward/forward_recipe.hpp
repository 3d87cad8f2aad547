#pragma once
#include <shadelgraph/render/frame_recipe.hpp>

namespace sg::plugins {

// Forward shading of every object: z-prepass, forward-opaque, alpha-mask and
// alpha-blend (each only if the scene has such materials), exposure (async
// compute), tonemap.
graph::ResourceHandle forwardRecipe(graph::RenderGraph& graph, const render::FrameInputs& inputs);

}  // namespace sg::plugins
