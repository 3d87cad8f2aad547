#include <shadelgraph/render/shadow_views.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace sg::render {
namespace {

bool castsShadowMap(const scene::Light& light) { return light.shadows && light.type == scene::LightType::Spot; }

// The cone's half angle with a margin, so the square frustum holds the whole cone and its PCF footprint.
float spotHalfAngle(const scene::Light& light) {
  return std::min(light.outerConeAngle * 1.05f + 0.01f, glm::radians(85.0f));
}

}  // namespace

bool lightReaches(const scene::Light& light, const glm::vec4& sphere) {
  if (light.type == scene::LightType::Directional) return true;
  const glm::vec3 v = glm::vec3(sphere) - light.position;
  const float distance = glm::length(v), radius = sphere.w;
  if (light.range > 0.0f && distance - radius > light.range) return false;
  if (light.type == scene::LightType::Point || distance <= radius) return true;
  // Sphere against cone: the centre's distance from the cone's surface, along the normal to it.
  const float along = glm::dot(v, light.direction);
  const float across = std::sqrt(std::max(distance * distance - along * along, 0.0f));
  const float angle = light.outerConeAngle;
  return across * std::cos(angle) - along * std::sin(angle) <= radius;
}

std::vector<ShadowView> shadowViews(std::span<const scene::Light> lights, std::span<const glm::vec4> spheres,
                                    uint32_t maxMaps) {
  std::vector<ShadowView> views;
  for (uint32_t i = 0; i < lights.size() && views.size() < maxMaps; ++i) {
    const scene::Light& light = lights[i];
    if (!castsShadowMap(light)) continue;
    const glm::vec3 dir = glm::normalize(light.direction);
    // Depth range: from the nearest to the farthest reached sphere along the axis (what casts or receives).
    float nearest = std::numeric_limits<float>::infinity(), farthest = 0.0f;
    for (const glm::vec4& s : spheres) {
      if (!lightReaches(light, s)) continue;
      const float along = glm::dot(glm::vec3(s) - light.position, dir);
      nearest = std::min(nearest, along - s.w);
      farthest = std::max(farthest, along + s.w);
    }
    if (light.range > 0.0f) farthest = std::min(farthest, light.range);
    if (!(farthest > 0.0f)) farthest = 1.0f;  // reaches nothing: any valid range
    const float zfar = farthest * 1.01f;
    const float znear = std::clamp(nearest * 0.99f, zfar * 1e-4f, zfar * 0.5f);
    const glm::vec3 up = std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::mat4 view = glm::lookAtRH(light.position, light.position + dir, up);
    const glm::mat4 projection = glm::perspectiveRH_ZO(2.0f * spotHalfAngle(light), 1.0f, znear, zfar);
    views.push_back({i, uint32_t(views.size()), projection * view});
  }
  return views;
}

}  // namespace sg::render
