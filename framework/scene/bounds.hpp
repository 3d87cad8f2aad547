#pragma once
// Axis-aligned bounding box. Starts empty (min > max) so extending is uniform.
#include <limits>

#include <glm/glm.hpp>

namespace sg::scene {

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  glm::vec3 center() const { return (min + max) * 0.5f; }
  glm::vec3 size() const { return empty() ? glm::vec3(0.0f) : max - min; }
  // Radius of the sphere around center() that holds the box.
  float radius() const { return empty() ? 0.0f : glm::length(max - min) * 0.5f; }

  void extend(const glm::vec3& point) {
    min = glm::min(min, point);
    max = glm::max(max, point);
  }
  void extend(const Bounds& other) {
    if (other.empty()) return;
    extend(other.min);
    extend(other.max);
  }
};

// The box around the eight transformed corners of `local`.
Bounds transformBounds(const Bounds& local, const glm::mat4& transform);

}  // namespace sg::scene
