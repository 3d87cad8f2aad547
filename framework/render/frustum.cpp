#include <shadelgraph/render/frustum.hpp>

#include <algorithm>
#include <cmath>

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

glm::ivec4 boxScreenRect(const glm::mat4& m, const scene::Bounds& box, uint32_t width, uint32_t height) {
  if (box.empty()) return {0, 0, 0, 0};
  const glm::ivec4 whole(0, 0, int(width), int(height));
  glm::vec2 lo(INFINITY), hi(-INFINITY);
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p(corner & 1 ? box.max.x : box.min.x, corner & 2 ? box.max.y : box.min.y,
                      corner & 4 ? box.max.z : box.min.z);
    const glm::vec4 clip = m * glm::vec4(p, 1.0f);
    if (clip.w <= 0.0f) return whole;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const glm::vec2 pixel((ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height));
    lo = glm::min(lo, pixel);
    hi = glm::max(hi, pixel);
  }
  const auto clampX = [&](float x) { return int(std::clamp(x, 0.0f, float(width))); };
  const auto clampY = [&](float y) { return int(std::clamp(y, 0.0f, float(height))); };
  return {clampX(std::floor(lo.x) - 1.0f), clampY(std::floor(lo.y) - 1.0f), clampX(std::ceil(hi.x) + 1.0f),
          clampY(std::ceil(hi.y) + 1.0f)};
}

}  // namespace sg::render
