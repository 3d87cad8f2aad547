#include <shadelgraph/scene/procedural_meshes.hpp>

#include <cmath>
#include <numbers>

namespace sg::scene {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Tangent handedness follows glTF: bitangent = cross(normal, tangent) * w
// points along -V (the image's up; V grows downwards), which is what the
// normal maps' +Y means. Each maker sets w accordingly.
void addVertex(Primitive& p, const glm::vec3& position, const glm::vec3& normal, const glm::vec3& tangent,
               const glm::vec2& uv) {
  p.positions.push_back(position);
  p.normals.push_back(glm::normalize(normal));
  p.tangents.emplace_back(glm::normalize(tangent), 1.0f);
  p.uv0.push_back(uv);
  p.bounds.extend(position);
}

// Two counter-clockwise triangles for the quad a-b-c-d (counter-clockwise seen from the front).
void addQuad(Primitive& p, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  p.indices.insert(p.indices.end(), {a, b, c, a, c, d});
}

// A grid of (nu+1) x (nv+1) vertices from a parametric surface; quads between them.
template <class Surface>
void addGrid(Primitive& p, int nu, int nv, Surface surface) {
  const auto base = static_cast<uint32_t>(p.positions.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      glm::vec3 position, normal, tangent;
      glm::vec2 uv;
      surface(float(i) / float(nu), float(j) / float(nv), position, normal, tangent, uv);
      addVertex(p, position, normal, tangent, uv);
    }
  const auto row = static_cast<uint32_t>(nu + 1);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      uint32_t a = base + uint32_t(j) * row + uint32_t(i);
      addQuad(p, a, a + row, a + row + 1, a + 1);
    }
}

}  // namespace

Primitive makeBox(const glm::vec3& size) {
  Primitive p;
  const glm::vec3 h = size * 0.5f;
  // normal, tangent (+U direction), bitangent (+V direction, UV v grows downwards in the atlas cell)
  struct Face {
    glm::vec3 n, t, b;
  };
  const Face faces[6] = {
      {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
      {{0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, -1, 0}},
  };
  constexpr float kPad = 0.02f;
  for (int f = 0; f < 6; ++f) {
    const Face& face = faces[f];
    const glm::vec2 cellMin{float(f % 3) / 3.0f, float(f / 3) / 2.0f};
    const glm::vec2 cellSize{1.0f / 3.0f, 0.5f};
    const glm::vec3 center = face.n * glm::dot(glm::abs(face.n), h);
    const float extentT = glm::dot(glm::abs(face.t), h), extentB = glm::dot(glm::abs(face.b), h);
    const auto base = static_cast<uint32_t>(p.positions.size());
    for (int corner = 0; corner < 4; ++corner) {
      const float su = (corner == 1 || corner == 2) ? 1.0f : 0.0f;
      const float sv = (corner >= 2) ? 1.0f : 0.0f;
      glm::vec3 position = center + face.t * extentT * (2 * su - 1) + face.b * extentB * (2 * sv - 1);
      glm::vec2 uv = cellMin + cellSize * (kPad + (1 - 2 * kPad) * glm::vec2(su, sv));
      addVertex(p, position, face.n, face.t, uv);
    }
    // Corners go +U then +V; with V pointing along `b` the front-facing winding
    // depends on whether cross(t, b) agrees with the normal.
    if (glm::dot(glm::cross(face.t, face.b), face.n) > 0)
      addQuad(p, base, base + 1, base + 2, base + 3);
    else
      addQuad(p, base, base + 3, base + 2, base + 1);
    // Handedness: bitangent = cross(normal, tangent) * w must point along -V.
    const float w = glm::dot(glm::cross(face.n, face.t), face.b) > 0 ? -1.0f : 1.0f;
    for (int corner = 0; corner < 4; ++corner) p.tangents[base + corner].w = w;
  }
  return p;
}

Primitive makePlane(float width, float depth, int subdivisions) {
  Primitive p;
  addGrid(p, subdivisions, subdivisions, [&](float u, float v, glm::vec3& pos, glm::vec3& n, glm::vec3& t, glm::vec2& uv) {
    pos = {(u - 0.5f) * width, 0.0f, (v - 0.5f) * depth};
    n = {0, 1, 0};
    t = {1, 0, 0};
    uv = {u, v};
  });
  // +V runs along +Z, so the bitangent must be -Z = cross(+Y, +X): handedness +1.
  for (auto& t : p.tangents) t.w = 1.0f;
  return p;
}

Primitive makeCylinder(float radius, float height, int segments) {
  Primitive p;
  addGrid(p, segments, 1, [&](float u, float v, glm::vec3& pos, glm::vec3& n, glm::vec3& t, glm::vec2& uv) {
    const float a = u * 2 * kPi;
    n = {std::cos(a), 0, -std::sin(a)};
    t = {-std::sin(a), 0, -std::cos(a)};
    pos = n * radius + glm::vec3(0, (1 - v) * height, 0);
    uv = {u, 0.02f + v * 0.56f};
  });
  for (auto& t : p.tangents) t.w = 1.0f;  // cross(n, t) = +Y, against +V (which runs down)
  // Caps: triangle fans around a centre vertex, each in its own disc of the chart.
  for (int cap = 0; cap < 2; ++cap) {
    const bool top = cap == 0;
    const glm::vec3 n{0, top ? 1.0f : -1.0f, 0};
    const glm::vec2 centerUv{top ? 0.25f : 0.75f, 0.8f};
    constexpr float kUvRadius = 0.18f;
    const float y = top ? height : 0.0f;
    const auto center = static_cast<uint32_t>(p.positions.size());
    addVertex(p, {0, y, 0}, n, {1, 0, 0}, centerUv);
    for (int i = 0; i <= segments; ++i) {
      // i % segments: the closing vertex repeats the first exactly (no sliver overlap at the seam).
      const float a = float(i % segments) / float(segments) * 2 * kPi;
      const glm::vec2 dir{std::cos(a), std::sin(a)};
      addVertex(p, {dir.x * radius, y, dir.y * radius}, n, {1, 0, 0}, centerUv + dir * kUvRadius);
    }
    for (int i = 0; i < segments; ++i) {
      const uint32_t a = center + 1 + uint32_t(i);
      if (top)
        p.indices.insert(p.indices.end(), {center, a + 1, a});
      else
        p.indices.insert(p.indices.end(), {center, a, a + 1});
    }
    const float w = top ? 1.0f : -1.0f;  // +V runs along +Z in both discs, the bitangent along -Z
    for (size_t i = center; i < p.tangents.size(); ++i) p.tangents[i].w = w;
  }
  return p;
}

Primitive makeSphere(float radius, int segments, int rings) {
  Primitive p;
  auto surface = [&](float u, float v, glm::vec3& pos, glm::vec3& n, glm::vec3& t, glm::vec2& uv) {
    const float a = u * 2 * kPi, polar = v * kPi;
    n = {std::sin(polar) * std::cos(a), std::cos(polar), -std::sin(polar) * std::sin(a)};
    t = {-std::sin(a), 0, -std::cos(a)};
    pos = n * radius;
    uv = {u, v};
  };
  // Rings between the polar caps as a grid; each pole a row of per-segment vertices.
  const auto base = static_cast<uint32_t>(p.positions.size());
  for (int j = 1; j < rings; ++j)
    for (int i = 0; i <= segments; ++i) {
      glm::vec3 pos, n, t;
      glm::vec2 uv;
      surface(float(i) / float(segments), float(j) / float(rings), pos, n, t, uv);
      addVertex(p, pos, n, t, uv);
    }
  const auto row = static_cast<uint32_t>(segments + 1);
  for (int j = 0; j + 1 < rings - 1; ++j)
    for (int i = 0; i < segments; ++i) {
      uint32_t a = base + uint32_t(j) * row + uint32_t(i);
      addQuad(p, a, a + row, a + row + 1, a + 1);
    }
  for (int pole = 0; pole < 2; ++pole) {
    const float v = pole == 0 ? 0.0f : 1.0f;
    const uint32_t ringStart = base + (pole == 0 ? 0u : uint32_t(rings - 2) * row);
    for (int i = 0; i < segments; ++i) {
      glm::vec3 pos, n, t;
      glm::vec2 uv;
      surface((float(i) + 0.5f) / float(segments), v, pos, n, t, uv);
      const auto tip = static_cast<uint32_t>(p.positions.size());
      addVertex(p, pos, n, t, uv);
      const uint32_t a = ringStart + uint32_t(i);
      if (pole == 0)
        p.indices.insert(p.indices.end(), {tip, a, a + 1});
      else
        p.indices.insert(p.indices.end(), {tip, a + 1, a});
    }
  }
  for (auto& t : p.tangents) t.w = 1.0f;  // as the cylinder: cross(n, t) points up, +V runs down
  return p;
}

Primitive makeTorus(float ringRadius, float tubeRadius, int ringSegments, int tubeSegments) {
  Primitive p;
  addGrid(p, ringSegments, tubeSegments, [&](float u, float v, glm::vec3& pos, glm::vec3& n, glm::vec3& t, glm::vec2& uv) {
    const float a = u * 2 * kPi, b = v * 2 * kPi;
    const glm::vec3 radial{std::cos(a), 0, -std::sin(a)};
    n = radial * std::cos(b) + glm::vec3(0, std::sin(b), 0);
    t = {-std::sin(a), 0, -std::cos(a)};
    pos = radial * ringRadius + n * tubeRadius;
    uv = {u, v};
  });
  // +V runs up the tube's outside, along cross(n, t) there: handedness -1.
  // addGrid's winding faces -(dP/du x dP/dv), which here points inwards.
  for (auto& t : p.tangents) t.w = -1.0f;
  for (size_t i = 0; i < p.indices.size(); i += 3) std::swap(p.indices[i + 1], p.indices[i + 2]);
  return p;
}

}  // namespace sg::scene
