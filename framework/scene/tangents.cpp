#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include <shadelgraph/scene/tangents.hpp>

namespace sg::scene {
namespace {

constexpr uint32_t kNone = ~0u;

// Some unit vector perpendicular to n.
glm::vec3 anyPerpendicular(const glm::vec3& n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::normalize(glm::cross(axis, n));
}

// v without its component along unit n, normalized (zero stays zero).
glm::vec3 inPlane(const glm::vec3& v, const glm::vec3& n) {
  const glm::vec3 p = v - n * glm::dot(n, v);
  const float length = glm::length(p);
  return length > 0.0f && std::isfinite(length) ? p / length : glm::vec3(0.0f);
}

// Corners with equal position, normal and UV (compared as values: -0 == 0)
// share one welded index.
std::vector<uint32_t> weldCorners(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                  std::span<const glm::vec2> uvs, std::span<const uint32_t> indices) {
  struct Key {
    float v[8];
    bool operator==(const Key& o) const { return std::equal(v, v + 8, o.v); }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const {
      uint64_t h = 1469598103934665603ull;
      for (const float f : k.v) {
        uint32_t bits = 0;
        std::memcpy(&bits, &f, sizeof bits);
        h = (h ^ bits) * 1099511628211ull;
      }
      return static_cast<size_t>(h);
    }
  };
  std::unordered_map<Key, uint32_t, KeyHash> ids;
  ids.reserve(positions.size());
  std::vector<uint32_t> byVertex(positions.size(), kNone);
  std::vector<uint32_t> welded(indices.size());
  for (size_t c = 0; c < indices.size(); ++c) {
    const uint32_t v = indices[c];
    if (byVertex[v] == kNone) {
      const glm::vec3 p = positions[v] + 0.0f, n = normals[v] + 0.0f;  // + 0: -0 becomes +0
      const glm::vec2 t = uvs[v] + 0.0f;
      byVertex[v] = ids.try_emplace(Key{{p.x, p.y, p.z, n.x, n.y, n.z, t.x, t.y}}, static_cast<uint32_t>(ids.size()))
                        .first->second;
    }
    welded[c] = byVertex[v];
  }
  return welded;
}

struct Triangle {
  glm::vec3 dPdu{0.0f};     // unit, or zero without a UV gradient
  bool orientPreserving = true;
  bool groupsWithAny = true;  // no UV gradient: joins the first group that reaches it
  bool degenerate = false;    // two corners at one position: takes its tangents from others
};

}  // namespace

std::vector<glm::vec4> cornerTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                      std::span<const glm::vec2> uvs, std::span<const uint32_t> indices) {
  const size_t corners = indices.size() - indices.size() % 3;
  const size_t triangleCount = corners / 3;
  const std::vector<uint32_t> welded = weldCorners(positions, normals, uvs, indices.first(corners));

  // Per triangle: unit dP/du and the orientation, in UVs with v pointing up
  // (v negated), where MikkTSpace's "orientation preserving" means w = +1.
  std::vector<Triangle> triangles(triangleCount);
  for (size_t f = 0; f < triangleCount; ++f) {
    Triangle& t = triangles[f];
    const glm::vec3 &p1 = positions[indices[3 * f]], &p2 = positions[indices[3 * f + 1]],
                    &p3 = positions[indices[3 * f + 2]];
    t.degenerate = p1 == p2 || p1 == p3 || p2 == p3;
    const glm::vec2 uv1 = uvs[indices[3 * f]] * glm::vec2(1, -1), uv2 = uvs[indices[3 * f + 1]] * glm::vec2(1, -1),
                    uv3 = uvs[indices[3 * f + 2]] * glm::vec2(1, -1);
    const glm::vec2 t21 = uv2 - uv1, t31 = uv3 - uv1;
    const glm::vec3 d1 = p2 - p1, d2 = p3 - p1;
    const float signedArea = t21.x * t31.y - t21.y * t31.x;
    t.orientPreserving = signedArea > 0.0f;
    const glm::vec3 os = d1 * t31.y - d2 * t21.y;  // dP/du times the signed area
    const glm::vec3 ot = d2 * t21.x - d1 * t31.x;  // dP/dv times the signed area
    const float lengthS = glm::length(os), lengthT = glm::length(ot);
    if (std::abs(signedArea) > 0.0f && lengthS > 0.0f && lengthT > 0.0f && std::isfinite(lengthS) &&
        std::isfinite(lengthT)) {
      t.dPdu = os * ((t.orientPreserving ? 1.0f : -1.0f) / lengthS);
      t.groupsWithAny = false;
    }
  }

  // Neighbours across edges: triangle f's edge e runs from corner e to e + 1;
  // the neighbour is wound the other way along it.
  const auto edgeKey = [](uint32_t a, uint32_t b) { return (uint64_t{a} << 32) | b; };
  std::unordered_map<uint64_t, uint32_t> edgeOwner;
  edgeOwner.reserve(corners);
  for (size_t f = 0; f < triangleCount; ++f) {
    if (triangles[f].degenerate) continue;
    for (uint32_t e = 0; e < 3; ++e)
      edgeOwner.try_emplace(edgeKey(welded[3 * f + e], welded[3 * f + (e + 1) % 3]), static_cast<uint32_t>(f));
  }
  const auto neighbour = [&](size_t f, uint32_t e) {
    const auto it = edgeOwner.find(edgeKey(welded[3 * f + (e + 1) % 3], welded[3 * f + e]));
    return it == edgeOwner.end() ? kNone : it->second;
  };

  // Groups: at each vertex, the triangles reachable from a seed across edges at
  // that vertex with the seed's orientation (triangles without a gradient take
  // the orientation of the first group that reaches them).
  std::vector<uint32_t> cornerGroup(corners, kNone);
  std::vector<bool> groupOrientation;
  std::vector<uint32_t> stack;
  const auto cornerOf = [&](uint32_t f, uint32_t vertex) {
    for (uint32_t i = 0; i < 3; ++i)
      if (welded[3 * f + i] == vertex) return i;
    return kNone;
  };
  for (size_t seedCorner = 0; seedCorner < corners; ++seedCorner) {
    const size_t seed = seedCorner / 3;
    if (cornerGroup[seedCorner] != kNone || triangles[seed].groupsWithAny || triangles[seed].degenerate) continue;
    const auto group = static_cast<uint32_t>(groupOrientation.size());
    const bool orientation = triangles[seed].orientPreserving;
    groupOrientation.push_back(orientation);
    const uint32_t vertex = welded[seedCorner];
    cornerGroup[seedCorner] = group;
    stack.assign(1, static_cast<uint32_t>(seed));
    while (!stack.empty()) {
      const uint32_t f = stack.back();
      stack.pop_back();
      const uint32_t i = cornerOf(f, vertex);
      for (const uint32_t e : {i, (i + 2) % 3}) {  // the two edges at this corner
        const uint32_t n = neighbour(f, e);
        if (n == kNone) continue;
        const uint32_t ni = cornerOf(n, vertex);
        if (ni == kNone || cornerGroup[3 * n + ni] != kNone) continue;
        Triangle& t = triangles[n];
        if (t.groupsWithAny && cornerGroup[3 * n] == kNone && cornerGroup[3 * n + 1] == kNone &&
            cornerGroup[3 * n + 2] == kNone)
          t.orientPreserving = orientation;
        if (t.orientPreserving != orientation) continue;
        cornerGroup[3 * n + ni] = group;
        stack.push_back(n);
      }
    }
  }

  // A group's tangent: its triangles' dP/du in the vertex normal's plane,
  // weighted by the corner angle in that plane.
  std::vector<glm::vec3> groupSum(groupOrientation.size(), glm::vec3(0.0f));
  for (size_t c = 0; c < corners; ++c) {
    const size_t f = c / 3;
    if (cornerGroup[c] == kNone || triangles[f].groupsWithAny) continue;
    const uint32_t i = static_cast<uint32_t>(c % 3);
    const glm::vec3 n = normals[indices[c]];
    const glm::vec3 p = positions[indices[c]];
    const glm::vec3 toNext = inPlane(positions[indices[3 * f + (i + 1) % 3]] - p, n);
    const glm::vec3 toPrevious = inPlane(positions[indices[3 * f + (i + 2) % 3]] - p, n);
    const float angle = std::acos(std::clamp(glm::dot(toNext, toPrevious), -1.0f, 1.0f));
    groupSum[cornerGroup[c]] += inPlane(triangles[f].dPdu, n) * angle;
  }

  std::vector<glm::vec4> tangents(corners);
  std::vector<uint32_t> groupedCornerOf(corners, kNone);  // welded vertex -> one of its grouped corners
  for (size_t c = 0; c < corners; ++c) {
    const glm::vec3 n = normals[indices[c]];
    const uint32_t g = cornerGroup[c];
    const glm::vec3 t = g == kNone ? glm::vec3(0.0f) : inPlane(groupSum[g], n);
    if (t == glm::vec3(0.0f)) {
      tangents[c] = glm::vec4(anyPerpendicular(n), 1.0f);
      continue;
    }
    tangents[c] = glm::vec4(t, groupOrientation[g] ? 1.0f : -1.0f);
    groupedCornerOf[welded[c]] = static_cast<uint32_t>(c);
  }
  // Corners no group reached (degenerate triangles, or no gradient anywhere
  // around them) take the tangent of another corner of their vertex.
  for (size_t c = 0; c < corners; ++c) {
    const uint32_t other = groupedCornerOf[welded[c]];
    if (cornerGroup[c] == kNone && other != kNone) tangents[c] = tangents[other];
  }
  tangents.resize(indices.size(), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));  // a trailing partial triangle has no say
  return tangents;
}

size_t addTangents(Primitive& p, int uvSet) {
  const std::vector<glm::vec4> corner = cornerTangents(p.positions, p.normals, p.uvs(uvSet), p.indices);
  const size_t original = p.positions.size();
  p.tangents.assign(original, glm::vec4(0.0f));
  std::vector<bool> assigned(original, false);
  std::unordered_map<uint32_t, std::vector<uint32_t>> copies;  // vertex -> its copies with other tangents
  const auto copyVertex = [&p](uint32_t v) {
    // Every per-vertex attribute array of Primitive (mesh.hpp), tangents last.
    p.positions.push_back(p.positions[v]);
    p.normals.push_back(p.normals[v]);
    if (!p.uv0.empty()) p.uv0.push_back(p.uv0[v]);
    if (!p.uv1.empty()) p.uv1.push_back(p.uv1[v]);
    if (!p.colors.empty()) p.colors.push_back(p.colors[v]);
    forEachDeformationAttribute(p, [v](auto& attribute) {
      if (!attribute.empty()) {
        const auto value = attribute[v];  // a copy: push_back may reallocate
        attribute.push_back(value);
      }
    });
    p.tangents.push_back(glm::vec4(0.0f));
    return static_cast<uint32_t>(p.positions.size() - 1);
  };
  for (size_t c = 0; c < p.indices.size(); ++c) {
    const uint32_t v = p.indices[c];
    if (!assigned[v]) {
      assigned[v] = true;
      p.tangents[v] = corner[c];
      continue;
    }
    if (p.tangents[v] == corner[c]) continue;
    std::vector<uint32_t>& mine = copies[v];
    const auto same = std::find_if(mine.begin(), mine.end(), [&](uint32_t k) { return p.tangents[k] == corner[c]; });
    if (same != mine.end()) {
      p.indices[c] = *same;
      continue;
    }
    const uint32_t k = copyVertex(v);
    p.tangents[k] = corner[c];
    mine.push_back(k);
    p.indices[c] = k;
  }
  for (size_t v = 0; v < original; ++v)  // vertices no triangle uses
    if (!assigned[v]) p.tangents[v] = glm::vec4(anyPerpendicular(p.normals[v]), 1.0f);
  return p.positions.size() - original;
}

}  // namespace sg::scene
