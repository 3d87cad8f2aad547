#include <cmath>

#include <shadelgraph/scene/tangents.hpp>

namespace sg::scene {
namespace {

// Some unit vector perpendicular to n.
glm::vec3 anyPerpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::normalize(glm::cross(axis, n));
}

}  // namespace

std::vector<glm::vec4> generateTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> uvs, std::span<const uint32_t> indices) {
  std::vector<glm::vec3> tangentSum(positions.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> bitangentSum(positions.size(), glm::vec3(0.0f));

  for (size_t corner = 0; corner + 2 < indices.size(); corner += 3) {
    const uint32_t i0 = indices[corner], i1 = indices[corner + 1], i2 = indices[corner + 2];
    const glm::vec3 e1 = positions[i1] - positions[i0];
    const glm::vec3 e2 = positions[i2] - positions[i0];
    const glm::vec2 d1 = uvs[i1] - uvs[i0];
    const glm::vec2 d2 = uvs[i2] - uvs[i0];
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-20f)) continue;  // no UV gradient: this triangle has no say
    // Solve [e1 e2] = [dPdu dPdv] * [d1 d2].
    const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
    const float lu = glm::length(dPdu), lv = glm::length(dPdv);
    if (!(lu > 0.0f) || !(lv > 0.0f) || !std::isfinite(lu) || !std::isfinite(lv)) continue;
    // Area weighting: large triangles dominate, slivers barely count.
    const float area = 0.5f * glm::length(glm::cross(e1, e2));
    const glm::vec3 t = dPdu / lu * area;
    const glm::vec3 b = dPdv / lv * area;
    for (uint32_t index : {i0, i1, i2}) {
      tangentSum[index] += t;
      bitangentSum[index] += b;
    }
  }

  std::vector<glm::vec4> tangents(positions.size());
  for (size_t v = 0; v < positions.size(); ++v) {
    const glm::vec3 n = normals[v];
    glm::vec3 t = tangentSum[v] - n * glm::dot(n, tangentSum[v]);
    const float length = glm::length(t);
    if (!(length > 1e-12f)) {
      tangents[v] = glm::vec4(anyPerpendicular(n), 1.0f);
      continue;
    }
    t /= length;
    // glTF's bitangent follows the image's +Y (up), i.e. decreasing v.
    const float w = glm::dot(glm::cross(n, t), -bitangentSum[v]) < 0.0f ? -1.0f : 1.0f;
    tangents[v] = glm::vec4(t, w);
  }
  return tangents;
}

}  // namespace sg::scene
