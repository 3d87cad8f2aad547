#include "mesh_edits.hpp"

#include <cmath>
#include <numbers>

namespace sg::test {
namespace {

void addVertex(scene::Primitive& p, const glm::vec3& position, const glm::vec2& uv) {
  p.positions.push_back(position);
  p.normals.emplace_back(0.0f, 1.0f, 0.0f);
  p.tangents.emplace_back(1.0f, 0.0f, 0.0f, 1.0f);  // +U along +X, +V along +Z (as makePlane)
  p.uv0.push_back(uv);
  p.bounds.extend(position);
}

}  // namespace

scene::Primitive unshared(const scene::Primitive& p) {
  scene::Primitive out;
  out.material = p.material;
  for (const uint32_t i : p.indices) {
    out.positions.push_back(p.positions[i]);
    out.normals.push_back(p.normals[i]);
    if (!p.tangents.empty()) out.tangents.push_back(p.tangents[i]);
    if (!p.uv0.empty()) out.uv0.push_back(p.uv0[i]);
    out.indices.push_back(uint32_t(out.indices.size()));
    out.bounds.extend(p.positions[i]);
  }
  return out;
}

scene::Primitive collapseUvs(scene::Primitive p, size_t every) {
  p = unshared(p);
  for (size_t t = 0; t < p.triangleCount(); t += every) {
    glm::vec2& a = p.uv0[3 * t];
    glm::vec2& b = p.uv0[3 * t + 1];
    glm::vec2& c = p.uv0[3 * t + 2];
    a = b = c = (a + b + c) / 3.0f;
  }
  return p;
}

scene::Primitive mirrorU(scene::Primitive p) {
  for (auto& uv : p.uv0) uv.x = 1.0f - uv.x;
  for (auto& t : p.tangents) t = glm::vec4(-glm::vec3(t), -t.w);
  return p;
}

scene::Primitive makeSliverDisc(int segments) {
  scene::Primitive p;
  addVertex(p, {0.0f, 0.0f, 0.0f}, {0.5f, 0.5f});
  for (int i = 0; i < segments; ++i) {
    const float a = float(i) / float(segments) * 2.0f * std::numbers::pi_v<float>;
    const glm::vec2 d{std::cos(a), std::sin(a)};
    addVertex(p, {d.x, 0.0f, d.y}, glm::vec2(0.5f) + 0.49f * d);
  }
  for (int i = 0; i < segments; ++i) {
    // Counter-clockwise seen from +Y: centre, next, this.
    p.indices.insert(p.indices.end(), {0u, uint32_t(1 + (i + 1) % segments), uint32_t(1 + i)});
  }
  return p;
}

scene::Primitive makeSliverStrips(float width, float depth, int strips) {
  scene::Primitive p;
  for (int i = 0; i <= strips; ++i) {
    const float u = float(i) / float(strips);
    addVertex(p, {(u - 0.5f) * width, 0.0f, -0.5f * depth}, {u, 0.0f});
    addVertex(p, {(u - 0.5f) * width, 0.0f, 0.5f * depth}, {u, 1.0f});
  }
  for (int i = 0; i < strips; ++i) {
    const uint32_t a = uint32_t(2 * i);  // a: far, a+1: near, a+2: next far, a+3: next near
    p.indices.insert(p.indices.end(), {a, a + 1, a + 3, a, a + 3, a + 2});
  }
  return p;
}

}  // namespace sg::test
