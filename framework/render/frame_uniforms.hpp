#pragma once
// The per-frame uniform block of framework/render/shaders/frame.glsl.
#include <glm/glm.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

constexpr int kMaxLights = 8;

struct GpuLight {
  glm::vec4 positionType;
  glm::vec4 directionRange;
  glm::vec4 color;
  glm::vec4 cone;
};

struct FrameUniforms {
  glm::mat4 view;
  glm::mat4 projection;
  glm::mat4 viewProjection;
  glm::vec4 cameraPosition;
  glm::vec4 ambient;
  glm::uvec4 counts;
  GpuLight lights[kMaxLights];
};

// A scene without lights gets a default sun so it is never black. Lights past
// kMaxLights are dropped (listed in `warnings` when given).
FrameUniforms makeFrameUniforms(const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                                uint32_t height);

}  // namespace sg::render
