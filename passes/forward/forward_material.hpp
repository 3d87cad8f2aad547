#pragma once
// Drawing objects with the forward (fragment) variant of their material:
// shared by forward-opaque, alpha-mask and alpha-blend.
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::passes {

// Opaque and masked draws write depth; blended ones test it and blend "over".
const gpu::Pipeline& forwardPipeline(PassContext& ctx, const render::SceneView& view, bool blend);
// Binds the draw's material set and draws it.
void drawWithMaterial(PassContext& ctx, const gpu::Pipeline& pipeline, const render::SceneView& view, uint32_t draw);
// Does the view hold a draw with this alpha mode?
bool hasAlphaMode(const render::SceneView& view, scene::AlphaMode mode);

}  // namespace sg::passes
