#pragma once
// The environment light's prefiltered maps in the passes that run material
// shaders (forward variants, decoupled layer-shade): the frame resources
// passes/environment writes, read when the frame has them and bound at
// kBindEnvironment*, or the scene's 1x1 white stand-in when the scene names
// no environment (frame.environment.x is 0 then and no material reads them).
#include <array>

#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/pass.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::render {

inline constexpr const char* kEnvironmentIrradianceResource = "environment.irradiance";
inline constexpr const char* kEnvironmentSpecularResource = "environment.specular";
inline constexpr const char* kEnvironmentBrdfResource = "environment.brdf";

// The bindings every material pipeline's set 0 has.
std::array<gpu::DescriptorBinding, 3> environmentBindings();
// Declares the reads of the frame's maps, if the view's frame has them.
void readEnvironment(graph::Pass& pass, const SceneView& view, graph::ShaderStage stage);
// The descriptors: this frame's maps, or the stand-in.
std::array<gpu::DescriptorWrite, 3> environmentWrites(PassContext& ctx, const SceneView& view);

}  // namespace sg::render
