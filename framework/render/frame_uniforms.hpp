#pragma once
// The per-frame uniforms (shaders/frame_interface.h), filled from the scene.
#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <shadelgraph/render/shaders/frame_interface.h>
#include <shadelgraph/render/shadow_views.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

using shader::kMaxLights;
using GpuLight = shader::Light;
using FrameUniforms = shader::SgFrameUniforms;

// The analytic sky's zenith luminance (cd/m^2; horizon 1.6x, ground 0.3x, gltf_pbr.glsl): a clear
// sky's zenith is about 4% of the sun's illuminance per steradian (a 100,000-lux sun: ~4,000 cd/m^2),
// from the brightest directional light; never dimmer than the 0.44 cd/m^2 blue sky this renderer
// always had, so scenes under a few-lux sun or only lamps keep their look.
inline constexpr float kSkyLuminancePerLux = 0.04f;
glm::vec3 skyLuminance(std::span<const scene::Light> lights);
// What the analytic sky is brightened by over that dim sky (1 or more): the
// background behind every object (forward-opaque's clear colour) follows it too.
float skyScale(std::span<const scene::Light> lights);

// A scene without lights gets a default sun so it is never black (it casts no
// shadow), unless it names an environment image, which lights it; `lights` receives the frame's lights (frame.counts.x of them, for
// kBindLights). A scene with more than kMaxLights is an error (Renderer's
// constructor). Shadowed lights get their maps' slots, matrices and cascade
// ends from `shadows` (render::shadowViews of the scene's lights, computed once per frame).
FrameUniforms makeFrameUniforms(const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                                uint32_t height, std::vector<GpuLight>& lights, std::span<const ShadowView> shadows = {});

}  // namespace sg::render
