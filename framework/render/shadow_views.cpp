#include <shadelgraph/render/shadow_views.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/render/frustum.hpp>

namespace sg::render {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

uint32_t mapsOf(const scene::Light& light) {
  switch (light.type) {
    case scene::LightType::Spot: return 1;
    case scene::LightType::Point: return 6;
    case scene::LightType::Directional: return kShadowCascades;
  }
  return 0;
}

glm::vec3 upFor(const glm::vec3& dir) { return std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0); }

// The cone's half angle with a margin, so the square frustum holds the whole cone and its PCF footprint.
float spotHalfAngle(const scene::Light& light) {
  return std::min(light.outerConeAngle * 1.05f + 0.01f, glm::radians(85.0f));
}

// Near and far of a perspective map from the light's position: the reached
// spheres' distances along `axis` (spot), or from the position (point: axis 0).
glm::vec2 depthRange(const scene::Light& light, std::span<const glm::vec4> spheres, const glm::vec3* axis) {
  float nearest = kInfinity, farthest = 0.0f;
  for (const glm::vec4& s : spheres) {
    if (!lightReaches(light, s)) continue;
    const glm::vec3 v = glm::vec3(s) - light.position;
    const float along = axis ? glm::dot(v, *axis) : glm::length(v);
    nearest = std::min(nearest, along - s.w);
    farthest = std::max(farthest, along + s.w);
  }
  if (light.range > 0.0f) farthest = std::min(farthest, light.range);
  if (!(farthest > 0.0f)) farthest = 1.0f;  // reaches nothing: any valid range
  const float zfar = farthest * 1.01f;
  return {std::clamp(nearest * 0.99f, zfar * 1e-4f, zfar * 0.5f), zfar};
}

glm::mat4 spotMatrix(const scene::Light& light, std::span<const glm::vec4> spheres) {
  const glm::vec3 dir = glm::normalize(light.direction);
  const glm::vec2 range = depthRange(light, spheres, &dir);
  const glm::mat4 view = glm::lookAtRH(light.position, light.position + dir, upFor(dir));
  return glm::perspectiveRH_ZO(2.0f * spotHalfAngle(light), 1.0f, range.x, range.y) * view;
}

// The six faces of a point light's cube, +X -X +Y -Y +Z -Z (lights.glsl picks
// the face by the major axis). A little over 90°, so the PCF footprint of a
// point at the edge of its face's region stays inside that face's map.
std::array<glm::mat4, 6> cubeMatrices(const scene::Light& light, std::span<const glm::vec4> spheres) {
  static const glm::vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const glm::vec2 range = depthRange(light, spheres, nullptr);
  const float fov = 2.0f * std::atan(1.0f + 8.0f / float(kShadowMapResolution));
  const glm::mat4 projection = glm::perspectiveRH_ZO(fov, 1.0f, range.x, range.y);
  std::array<glm::mat4, 6> faces;
  for (int f = 0; f < 6; ++f)
    faces[f] = projection * glm::lookAtRH(light.position, light.position + kAxes[f], upFor(kAxes[f]));
  return faces;
}

// Where each cascade ends, in view depth: the practical split scheme (a blend
// of logarithmic and uniform) between the camera's near plane and the
// farthest visible sphere, that far distance rounded up to a power of 2^(1/4)
// so the cascades' sizes (and so their texels) hold still while the visible
// range changes a little.
std::array<float, kShadowCascades> cascadeEnds(std::span<const glm::vec4> spheres, const ShadowCamera& camera) {
  const glm::mat4 viewProjection = camera.projection * camera.view;
  float farthest = 0.0f;
  for (const glm::vec4& s : spheres)
    if (sphereInFrustum(viewProjection, s))
      farthest = std::max(farthest, -(camera.view * glm::vec4(glm::vec3(s), 1.0f)).z + s.w);
  const float n = camera.znear;
  float f = std::exp2(std::ceil(std::log2(std::max(farthest, 2.0f * n)) * 4.0f) / 4.0f);
  if (camera.zfar) f = std::min(f, *camera.zfar);
  std::array<float, kShadowCascades> ends{};
  for (uint32_t i = 0; i < kShadowCascades; ++i) {
    const float t = float(i + 1) / float(kShadowCascades);
    ends[i] = glm::mix(n + (f - n) * t, n * std::pow(f / n, t), 0.75f);
  }
  ends.back() = f;
  return ends;
}

// The point of the camera's view space at view depth `depth` on the ray through NDC (x, y).
glm::vec3 viewPointAt(const glm::mat4& inverseProjection, float x, float y, float depth) {
  const glm::vec4 a = inverseProjection * glm::vec4(x, y, 0.0f, 1.0f), b = inverseProjection * glm::vec4(x, y, 0.5f, 1.0f);
  const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
  return p0 + (p1 - p0) * ((-depth - p0.z) / (p1.z - p0.z));
}

// A directional light's cascades. Each is an orthographic map around the
// bounding sphere of its slice of the view frustum (computed in view space,
// so its size does not change as the camera turns or moves), its centre
// snapped to whole texels in the light's space (so the texels do not crawl
// as the camera moves), its depth reaching back to every caster in front of the slice.
std::vector<ShadowView> cascades(uint32_t lightIndex, const scene::Light& light, std::span<const glm::vec4> spheres,
                                 const ShadowCamera& camera, uint32_t firstSlot) {
  const auto ends = cascadeEnds(spheres, camera);
  const glm::mat4 inverseProjection = glm::inverse(camera.projection), inverseView = glm::inverse(camera.view);
  const glm::vec3 dir = glm::normalize(light.direction);
  const glm::mat4 lightView = glm::lookAtRH(glm::vec3(0.0f), dir, upFor(dir));  // rotation only
  std::vector<ShadowView> views;
  for (uint32_t i = 0; i < kShadowCascades; ++i) {
    // A cascade also covers the band of the one before it that lights.glsl blends into it.
    const float before = i >= 2 ? ends[i - 2] : 0.0f;
    const float start = i == 0 ? camera.znear : ends[i - 1] - shader::kCascadeBlend * (ends[i - 1] - before);
    std::array<glm::vec3, 8> corners;
    glm::vec3 centre(0.0f);
    for (int c = 0; c < 8; ++c) {
      corners[c] = viewPointAt(inverseProjection, c & 1 ? 1.0f : -1.0f, c & 2 ? 1.0f : -1.0f, c & 4 ? ends[i] : start);
      centre += corners[c] / 8.0f;
    }
    float radius = 0.0f;
    for (const glm::vec3& c : corners) radius = std::max(radius, glm::distance(c, centre));
    // Rounding noise must not change the texel size: up to 1/64 of the radius's power of two (any scale).
    const float grain = std::exp2(std::floor(std::log2(std::max(radius, 1e-30f)))) / 64.0f;
    radius = std::ceil(radius / grain) * grain;
    const float half = radius * (1.0f + 8.0f / float(kShadowMapResolution));  // room for the PCF footprint and the snap
    const float texel = 2.0f * half / float(kShadowMapResolution);
    glm::vec3 c = glm::vec3(lightView * (inverseView * glm::vec4(centre, 1.0f)));
    c.x = std::round(c.x / texel) * texel;
    c.y = std::round(c.y / texel) * texel;
    // Depth (-z in light space): the slice, and back towards the light to every caster over it.
    float nearest = -c.z - radius;
    const float farthest = -c.z + radius;
    for (const glm::vec4& s : spheres) {
      const glm::vec3 p = glm::vec3(lightView * glm::vec4(glm::vec3(s), 1.0f));
      if (std::abs(p.x - c.x) <= half + s.w && std::abs(p.y - c.y) <= half + s.w) nearest = std::min(nearest, -p.z - s.w);
    }
    const float margin = 0.01f * (farthest - nearest);
    const glm::mat4 projection =
        glm::orthoRH_ZO(c.x - half, c.x + half, c.y - half, c.y + half, nearest - margin, farthest + margin);
    views.push_back({lightIndex, firstSlot + i, i, projection * lightView, ends[i]});
  }
  return views;
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
                                    const ShadowCamera& camera) {
  const glm::mat4 viewProjection = camera.projection * camera.view;
  std::vector<ShadowView> views;
  for (uint32_t i = 0; i < lights.size(); ++i) {
    const scene::Light& light = lights[i];
    const uint32_t maps = mapsOf(light);
    if (!light.shadows || views.size() + maps > kMaxShadowMaps) continue;
    const auto reachesVisible = [&](const glm::vec4& s) {
      return sphereInFrustum(viewProjection, s) && lightReaches(light, s);
    };
    if (std::none_of(spheres.begin(), spheres.end(), reachesVisible)) continue;
    const auto slot = uint32_t(views.size());
    switch (light.type) {
      case scene::LightType::Spot: views.push_back({i, slot, 0, spotMatrix(light, spheres)}); break;
      case scene::LightType::Point: {
        const auto faces = cubeMatrices(light, spheres);
        for (uint32_t f = 0; f < 6; ++f) views.push_back({i, slot + f, f, faces[f]});
        break;
      }
      case scene::LightType::Directional: {
        const auto c = cascades(i, light, spheres, camera, slot);
        views.insert(views.end(), c.begin(), c.end());
        break;
      }
    }
  }
  return views;
}

bool castsInto(const ShadowView& view, const scene::Light& light, const glm::vec4& sphere) {
  return lightReaches(light, sphere) && sphereInFrustum(view.viewProjection, sphere);
}

bool shadowMayFallOn(const scene::Light& light, const glm::vec4& caster, const glm::vec4& receiver) {
  const glm::vec3 c(caster), r(receiver);
  const float reach = caster.w + receiver.w;
  if (light.type == scene::LightType::Directional) {
    const glm::vec3 dir = glm::normalize(light.direction), v = r - c;
    const float along = glm::dot(v, dir);
    return along >= -reach && glm::length(v - dir * along) <= reach;  // behind the caster, within the cylinder
  }
  const glm::vec3 toCaster = c - light.position, toReceiver = r - light.position;
  const float dc = glm::length(toCaster), dr = glm::length(toReceiver);
  if (dc <= caster.w || dr <= receiver.w) return true;  // the light inside one of them
  if (dr + receiver.w < dc - caster.w) return false;    // wholly nearer the light than the caster
  const float cone = std::asin(std::min(caster.w / dc, 1.0f)) + std::asin(std::min(receiver.w / dr, 1.0f));
  const float angle = std::acos(std::clamp(glm::dot(toCaster, toReceiver) / (dc * dr), -1.0f, 1.0f));
  return angle <= cone;
}

glm::uvec2 shadowAtlasMaps(uint32_t maps) {
  const uint32_t columns = std::clamp(maps, 1u, kShadowAtlasColumns);
  return {columns, std::max((maps + columns - 1) / columns, 1u)};
}

}  // namespace sg::render
