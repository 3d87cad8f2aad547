#pragma once
// The lights in the passes that run material shaders (forward variants,
// decoupled layer-shade): the frame's light buffer at kBindLights, and the
// light grid at kBindLightGrid — the frame resource passes/light-cull writes
// when the frame has many lights, read when the frame has it, else a stand-in
// whose header says "no grid" (every light loop then visits every light).
#include <array>

#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/pass.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::render {

inline constexpr const char* kLightGridResource = "light.grid";

// The bindings every material pipeline's set 0 has.
std::array<gpu::DescriptorBinding, 2> lightBindings();
// Declares the read of the frame's light grid, if the view's frame has one.
void readLightGrid(graph::Pass& pass, const SceneView& view, graph::ShaderStage stage);
// The descriptors: the frame's lights, and its grid or the stand-in.
std::array<gpu::DescriptorWrite, 2> lightWrites(PassContext& ctx, const SceneView& view);

}  // namespace sg::render
