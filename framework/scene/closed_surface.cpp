#include <shadelgraph/scene/closed_surface.hpp>

#include <algorithm>
#include <numeric>
#include <vector>

#include <meshoptimizer.h>

namespace sg::scene {
namespace {

// Union-find over welded vertices, to split the surface into its edge-connected parts.
struct Parts {
  std::vector<uint32_t> parent;
  explicit Parts(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];  // path halving
    return v;
  }
  void unite(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

// Every undirected edge {lo, hi} is filed under lo as hi * 2 + (1 when it runs
// lo -> hi): a closed, consistently wound surface files exactly the pair
// 2hi, 2hi + 1 for each neighbour hi.
bool edgesPairUp(const std::vector<uint32_t>& triangles, size_t vertexCount) {
  std::vector<uint32_t> start(vertexCount + 1, 0);
  auto forEachEdge = [&](auto&& f) {
    for (size_t t = 0; t < triangles.size(); t += 3)
      for (size_t e = 0; e < 3; ++e) f(triangles[t + e], triangles[t + (e + 1) % 3]);
  };
  forEachEdge([&](uint32_t a, uint32_t b) { ++start[std::min(a, b) + 1]; });
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> filed(start.back());
  std::vector<uint32_t> next(start.begin(), start.end() - 1);
  forEachEdge([&](uint32_t a, uint32_t b) { filed[next[std::min(a, b)]++] = std::max(a, b) * 2 + (a < b ? 1 : 0); });
  for (size_t v = 0; v < vertexCount; ++v) {
    const auto first = filed.begin() + start[v], last = filed.begin() + start[v + 1];
    if ((last - first) % 2 != 0) return false;
    std::sort(first, last);
    for (auto it = first; it != last; it += 2)
      if (it[0] % 2 != 0 || it[1] != it[0] + 1) return false;
  }
  return true;
}

}  // namespace

bool isClosedSurface(std::span<const glm::vec3> positions, std::span<const uint32_t> indices) {
  if (indices.empty() || indices.size() % 3 != 0) return false;
  for (uint32_t i : indices)
    if (i >= positions.size()) return false;
  // Welded index per vertex (unreferenced vertices get ~0u, and no triangle names them).
  std::vector<uint32_t> weld(positions.size());
  const size_t welded = meshopt_generateVertexRemap(weld.data(), indices.data(), indices.size(), positions.data(),
                                                    positions.size(), sizeof(glm::vec3));
  // Triangles whose corners weld together cover no area and take no part.
  std::vector<uint32_t> triangles;
  triangles.reserve(indices.size());
  for (size_t t = 0; t < indices.size(); t += 3) {
    const uint32_t a = weld[indices[t]], b = weld[indices[t + 1]], c = weld[indices[t + 2]];
    if (a == b || b == c || a == c) continue;
    triangles.insert(triangles.end(), {a, b, c});
  }
  if (triangles.empty() || !edgesPairUp(triangles, welded)) return false;

  // Each part's signed volume (sum of the tetrahedra to the origin, times 6):
  // positive when its triangles wind counter-clockwise seen from outside.
  std::vector<glm::dvec3> at(welded);
  for (size_t i = 0; i < weld.size(); ++i)
    if (weld[i] != ~0u) at[weld[i]] = glm::dvec3(positions[i]);
  Parts parts(welded);
  for (size_t t = 0; t < triangles.size(); t += 3) {
    parts.unite(triangles[t], triangles[t + 1]);
    parts.unite(triangles[t], triangles[t + 2]);
  }
  std::vector<double> volume(welded, 0.0);
  std::vector<bool> kept(welded, false);  // a part whose vertices are only in degenerate triangles has none
  for (size_t t = 0; t < triangles.size(); t += 3) {
    const glm::dvec3 &p0 = at[triangles[t]], &p1 = at[triangles[t + 1]], &p2 = at[triangles[t + 2]];
    const uint32_t part = parts.find(triangles[t]);
    volume[part] += glm::dot(p0, glm::cross(p1, p2));
    kept[part] = true;
  }
  for (size_t v = 0; v < welded; ++v)
    if (parts.parent[v] == v && kept[v] && volume[v] <= 0.0) return false;
  return true;
}

}  // namespace sg::scene
