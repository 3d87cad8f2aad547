#include "object_picker.hpp"

#include <cmath>
#include <limits>

namespace sg::app::view {
namespace {

// Möller-Trumbore: distance along the ray, or +inf.
float hitTriangle(const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
  const float det = glm::dot(e1, p);
  if (std::abs(det) < 1e-12f) return std::numeric_limits<float>::infinity();
  const float inv = 1.0f / det;
  const glm::vec3 s = o - a;
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return std::numeric_limits<float>::infinity();
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return std::numeric_limits<float>::infinity();
  const float t = glm::dot(e2, q) * inv;
  return t > 0.0f ? t : std::numeric_limits<float>::infinity();
}

// Slab test of a mesh-space box.
bool hitBox(const glm::vec3& o, const glm::vec3& d, const scene::Bounds& b) {
  float near = 0.0f, far = std::numeric_limits<float>::infinity();
  for (int i = 0; i < 3; ++i) {
    const float inv = 1.0f / d[i];
    float t0 = (b.min[i] - o[i]) * inv, t1 = (b.max[i] - o[i]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far;
}

}  // namespace

std::optional<uint32_t> pickObject(const scene::Scene& scene, const std::vector<glm::mat4>& worlds,
                                   const scene::Camera& camera, uint32_t width, uint32_t height, double x, double y) {
  const glm::mat4 inverse = glm::inverse(camera.projectionMatrix(float(width) / float(height)) * camera.view());
  // Pixel centre to clip space (the projection's +Y is up, the window's down).
  const float cx = float((x + 0.5) / width * 2.0 - 1.0), cy = float(1.0 - (y + 0.5) / height * 2.0);
  glm::vec4 nearPoint = inverse * glm::vec4(cx, cy, 0.0f, 1.0f), farPoint = inverse * glm::vec4(cx, cy, 0.5f, 1.0f);
  const glm::vec3 origin = glm::vec3(nearPoint) / nearPoint.w;
  const glm::vec3 direction = glm::normalize(glm::vec3(farPoint) / farPoint.w - origin);
  std::optional<uint32_t> best;
  float bestDistance = std::numeric_limits<float>::infinity();
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const auto& mesh = scene.meshes[size_t(scene.instances[i].mesh)];
    const glm::mat4 toMesh = glm::inverse(worlds[i]);
    const glm::vec3 o = glm::vec3(toMesh * glm::vec4(origin, 1.0f));
    const glm::vec3 d = glm::vec3(toMesh * glm::vec4(direction, 0.0f));
    if (!hitBox(o, d, mesh.bounds)) continue;
    for (const auto& prim : mesh.primitives)
      for (size_t t = 0; t + 2 < prim.indices.size(); t += 3) {
        const float s = hitTriangle(o, d, prim.positions[prim.indices[t]], prim.positions[prim.indices[t + 1]],
                                    prim.positions[prim.indices[t + 2]]);
        if (s == std::numeric_limits<float>::infinity()) continue;
        // Distances compare in world space: mesh-space t scales with the transform.
        const glm::vec3 hit = glm::vec3(worlds[i] * glm::vec4(o + d * s, 1.0f));
        const float distance = glm::length(hit - origin);
        if (distance < bestDistance) {
          bestDistance = distance;
          best = i;
        }
      }
  }
  return best;
}

}  // namespace sg::app::view
