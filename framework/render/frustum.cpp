#include <shadelgraph/render/frustum.hpp>

namespace sg::render {

bool sphereInFrustum(const glm::mat4& m, const glm::vec4& sphere) {
  // Gribb & Hartmann: the planes are sums of the matrix's rows.
  const glm::vec4 row0(m[0][0], m[1][0], m[2][0], m[3][0]), row1(m[0][1], m[1][1], m[2][1], m[3][1]),
      row2(m[0][2], m[1][2], m[2][2], m[3][2]), row3(m[0][3], m[1][3], m[2][3], m[3][3]);
  const glm::vec4 planes[6] = {row3 + row0, row3 - row0, row3 + row1, row3 - row1, row2, row3 - row2};
  for (const glm::vec4& plane : planes) {
    const float length = glm::length(glm::vec3(plane));
    if (length == 0.0f) continue;  // an infinite far plane
    if (glm::dot(glm::vec3(plane), glm::vec3(sphere)) + plane.w < -sphere.w * length) return false;
  }
  return true;
}

bool sphereBeyondNearPlane(const glm::mat4& m, const glm::vec4& sphere) {
  const glm::vec4 near(m[0][2], m[1][2], m[2][2], m[3][2]);  // row 2: clip z >= 0
  return glm::dot(glm::vec3(near), glm::vec3(sphere)) + near.w > sphere.w * glm::length(glm::vec3(near));
}

}  // namespace sg::render
