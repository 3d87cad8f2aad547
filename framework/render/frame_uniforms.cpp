#include <shadelgraph/render/frame_uniforms.hpp>

#include <algorithm>
#include <cmath>

#include <shadelgraph/render/shadow_views.hpp>

namespace sg::render {

FrameUniforms makeFrameUniforms(const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                                uint32_t height, std::vector<GpuLight>& gpuLights,
                                std::span<const glm::vec4> drawSpheres) {
  FrameUniforms f{};
  f.view = camera.view();
  f.projection = camera.projectionMatrix(float(width) / float(height));
  f.viewProjection = f.projection * f.view;
  f.cameraPosition = glm::vec4(camera.position(), 1.0f);
  f.ambient = glm::vec4(0.35f, 0.45f, 0.6f, 0.0f);  // sky radiance
  std::vector<scene::Light> lights = scene.lights;
  if (lights.empty())
    lights.push_back({.name = "default sun", .type = scene::LightType::Directional, .color = glm::vec3(1.0f),
                      .intensity = 3.0f, .direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f))});
  const auto count = std::min<size_t>(lights.size(), kMaxLights);
  gpuLights.assign(count, GpuLight{});
  for (size_t i = 0; i < count; ++i) {
    const auto& l = lights[i];
    GpuLight& g = gpuLights[i];
    g.positionType = glm::vec4(l.position, float(int(l.type)));
    g.directionRange = glm::vec4(glm::normalize(l.direction), l.range);
    g.color = glm::vec4(l.color * l.intensity, 0.0f);
    const float cosOuter = std::cos(l.outerConeAngle), cosInner = std::cos(l.innerConeAngle);
    g.cone = glm::vec4(cosOuter, 1.0f / std::max(cosInner - cosOuter, 1e-4f), 0.0f, 0.0f);
  }
  f.counts = glm::uvec4(uint32_t(count), width, height, 0u);
  const auto views = shadowViews(std::span(lights).first(count), drawSpheres, kMaxShadowMaps);
  for (const ShadowView& v : views) {
    gpuLights[v.light].cone.z = float(v.slot + 1);
    gpuLights[v.light].shadowMatrix = v.viewProjection;
  }
  f.shadowAtlas = glm::vec4(float(views.size()), float(kShadowMapResolution), 0.0f, 0.0f);
  return f;
}

}  // namespace sg::render
