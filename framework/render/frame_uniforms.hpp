#pragma once
// The per-frame uniforms (shaders/frame_interface.h), filled from the scene.
#include <glm/glm.hpp>
#include <shadelgraph/render/shaders/frame_interface.h>

#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

using shader::kMaxLights;
using GpuLight = shader::Light;
using FrameUniforms = shader::SgFrameUniforms;

// A scene without lights gets a default sun so it is never black. Lights past
// kMaxLights are dropped (listed in `warnings` when given).
FrameUniforms makeFrameUniforms(const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                                uint32_t height);

}  // namespace sg::render
