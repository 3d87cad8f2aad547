#include <shadelgraph/scene/bounds.hpp>

namespace sg::scene {

Bounds transformBounds(const Bounds& local, const glm::mat4& transform) {
  Bounds result;
  if (local.empty()) return result;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                      (corner & 4) ? local.max.z : local.min.z};
    result.extend(glm::vec3(transform * glm::vec4(p, 1.0f)));
  }
  return result;
}

}  // namespace sg::scene
