#pragma once
// Catmull-Rom through p1..p2 with knots t0..t3 (Barry-Goldman pyramid): what
// camera paths and object paths interpolate their keys with.
#include <glm/glm.hpp>

namespace sg::scene {

inline glm::vec3 catmullRom(const glm::vec3 (&p)[4], const float (&t)[4], float time) {
  const auto lerp = [time](const glm::vec3& a, const glm::vec3& b, float ta, float tb) {
    return (a * (tb - time) + b * (time - ta)) / (tb - ta);
  };
  const glm::vec3 a1 = lerp(p[0], p[1], t[0], t[1]);
  const glm::vec3 a2 = lerp(p[1], p[2], t[1], t[2]);
  const glm::vec3 a3 = lerp(p[2], p[3], t[2], t[3]);
  const glm::vec3 b1 = lerp(a1, a2, t[0], t[2]);
  const glm::vec3 b2 = lerp(a2, a3, t[1], t[3]);
  return lerp(b1, b2, t[1], t[2]);
}

}  // namespace sg::scene
