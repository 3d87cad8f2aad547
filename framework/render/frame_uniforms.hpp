#pragma once
// The per-frame uniforms (shaders/frame_interface.h), filled from the scene.
#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <shadelgraph/render/shaders/frame_interface.h>

#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

using shader::kMaxLights;
using GpuLight = shader::Light;
using FrameUniforms = shader::SgFrameUniforms;

// The most shadow maps a frame draws (the atlas's columns); lights after that stay unshadowed.
inline constexpr uint32_t kMaxShadowMaps = 8;

// A scene without lights gets a default sun so it is never black; `lights`
// receives the frame's lights (frame.counts.x of them, for kBindLights). A
// scene with more than kMaxLights is an error (Renderer's constructor).
// Shadowed lights get their shadow map's slot and matrix (render::shadowViews,
// fitted to `drawSpheres`, every draw's world bounding sphere).
FrameUniforms makeFrameUniforms(const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                                uint32_t height, std::vector<GpuLight>& lights,
                                std::span<const glm::vec4> drawSpheres = {});

}  // namespace sg::render
