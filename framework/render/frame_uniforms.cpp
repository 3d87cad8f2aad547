#include <shadelgraph/render/frame_uniforms.hpp>

#include <algorithm>
#include <cmath>


namespace sg::render {

namespace {
const glm::vec3 kDimSky(0.35f, 0.45f, 0.6f);  // luminance 0.44 cd/m^2
const glm::vec3 kLuma(0.2126f, 0.7152f, 0.0722f);
}  // namespace

float skyScale(std::span<const scene::Light> lights) {
  float sun = 0.0f;  // the brightest directional light's illuminance, lux
  for (const auto& l : lights)
    if (l.type == scene::LightType::Directional) sun = std::max(sun, l.intensity * glm::dot(l.color, kLuma));
  return std::max(1.0f, kSkyLuminancePerLux * sun / glm::dot(kDimSky, kLuma));
}

glm::vec3 skyLuminance(std::span<const scene::Light> lights) { return kDimSky * skyScale(lights); }

FrameUniforms makeFrameUniforms(const scene::Scene& scene, const scene::Camera& camera, uint32_t width,
                                uint32_t height, std::vector<GpuLight>& gpuLights,
                                std::span<const ShadowView> shadows) {
  FrameUniforms f{};
  f.view = camera.view();
  f.projection = camera.projectionMatrix(float(width) / float(height));
  f.viewProjection = f.projection * f.view;
  f.cameraPosition = glm::vec4(camera.position(), 1.0f);
  std::vector<scene::Light> lights = scene.lights;
  f.ambient = glm::vec4(skyLuminance(lights), 0.0f);
  if (scene.environment.present()) f.environment = glm::vec4(1.0f, scene.environment.intensity, 0.0f, 0.0f);
  // No default sun under an environment image: the image is the scene's light (a sun of its own would add a highlight and a terminator it does not have).
  if (lights.empty() && !scene.environment.present())
    lights.push_back({.name = "default sun", .type = scene::LightType::Directional, .color = glm::vec3(1.0f),
                      .intensity = 3.0f, .direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f)),
                      .shadows = false});
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
  for (const ShadowView& v : shadows) {
    if (v.light >= count) continue;
    GpuLight& g = gpuLights[v.light];
    if (v.face == 0) {
      g.cone.z = float(v.slot + 1);
      g.shadowMatrix = v.viewProjection;
    }
    if (v.face < kShadowCascades) g.cascadeEnds[int(v.face)] = v.cascadeEnd;
    f.shadowMatrices[v.slot] = v.viewProjection;
  }
  f.shadowAtlas = glm::vec4(float(shadows.size()), float(kShadowMapResolution),
                            float(shadowAtlasMaps(uint32_t(shadows.size())).x), 0.0f);
  return f;
}

}  // namespace sg::render
