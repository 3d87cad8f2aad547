#pragma once
// The per-frame uniforms (shaders/frame_interface.h), filled from the scene.
#include <span>

#include <glm/glm.hpp>
#include <shadelgraph/render/shaders/frame_interface.h>
#include <shadelgraph/render/shadow_views.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

using shader::kMaxLights;
using GpuLight = shader::Light;
using FrameUniforms = shader::SgFrameUniforms;

// A scene without lights gets a default sun so it is never black. Lights past
// kMaxLights are dropped (the default sun casts no shadow). Shadowed lights
// get their maps' slots, matrices and cascade ends from `shadows`
// (render::shadowViews of the scene's lights, computed once per frame).
FrameUniforms makeFrameUniforms(const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                                uint32_t height, std::span<const ShadowView> shadows = {});

}  // namespace sg::render
