#pragma once
// The shadow atlas in the passes that run material shaders (forward variants,
// decoupled layer-shade): the frame resource passes/shadows writes, read when
// the frame has it, and bound at kBindShadowMaps, or a white stand-in when the
// frame drew no maps (no shadowed light reaches a visible object).
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/pass.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::render {

inline constexpr const char* kShadowMapsResource = "shadow.maps";

// The binding every material pipeline's set 0 has.
gpu::DescriptorBinding shadowMapsBinding();
// Declares the read of the frame's atlas, if the view's frame has one.
void readShadowMaps(graph::Pass& pass, const SceneView& view, graph::ShaderStage stage);
// The descriptor: this frame's atlas, or the scene's white texture.
gpu::DescriptorWrite shadowMapsWrite(PassContext& ctx, const SceneView& view);

}  // namespace sg::render
