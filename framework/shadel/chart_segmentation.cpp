#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <numeric>
#include <unordered_map>

#include <shadelgraph/shadel/chart_segmentation.hpp>

namespace sg::shadel {
namespace {

constexpr uint32_t kUnassigned = 0xFFFFFFFFu;

// Exact position equality, with -0 and +0 alike.
struct PositionKey {
  uint32_t bits[3];
  explicit PositionKey(const glm::vec3& p) {
    for (int i = 0; i < 3; ++i) {
      const float v = p[i] + 0.0f;
      std::memcpy(&bits[i], &v, sizeof v);
    }
  }
  bool operator==(const PositionKey& o) const { return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2]; }
};
struct PositionHash {
  size_t operator()(const PositionKey& k) const {
    return (size_t{k.bits[0]} * 0x9E3779B1u) ^ (size_t{k.bits[1]} * 0x85EBCA77u) ^ (size_t{k.bits[2]} * 0xC2B2AE3Du);
  }
};

}  // namespace

FlatTriangles::FlatTriangles(const scene::Mesh& mesh) {
  for (const scene::Primitive& primitive : mesh.primitives) {
    for (size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
      positions.push_back({glm::dvec3(primitive.positions[primitive.indices[i]]),
                           glm::dvec3(primitive.positions[primitive.indices[i + 1]]),
                           glm::dvec3(primitive.positions[primitive.indices[i + 2]])});
    }
  }
}

glm::dvec3 FlatTriangles::areaNormal(size_t t) const {
  const auto& p = positions[t];
  return glm::cross(p[1] - p[0], p[2] - p[0]);
}

std::vector<std::vector<uint32_t>> edgeAdjacency(const scene::Mesh& mesh) {
  std::vector<std::vector<uint32_t>> adjacency;
  uint32_t base = 0;
  for (const scene::Primitive& primitive : mesh.primitives) {
    std::unordered_map<PositionKey, uint32_t, PositionHash> welded;
    std::vector<uint32_t> weldedId(primitive.positions.size());
    for (size_t v = 0; v < primitive.positions.size(); ++v)
      weldedId[v] = welded.try_emplace(PositionKey(primitive.positions[v]), static_cast<uint32_t>(welded.size())).first->second;
    std::unordered_map<uint64_t, std::vector<uint32_t>> edges;  // welded (min, max) -> triangles
    const auto triangles = static_cast<uint32_t>(primitive.triangleCount());
    for (uint32_t t = 0; t < triangles; ++t)
      for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t a = weldedId[primitive.indices[3 * t + k]], b = weldedId[primitive.indices[3 * t + (k + 1) % 3]];
        if (a == b) continue;
        edges[(uint64_t{std::min(a, b)} << 32) | std::max(a, b)].push_back(base + t);
      }
    adjacency.resize(base + triangles);
    for (const auto& [edge, sharing] : edges)
      if (sharing.size() == 2 && sharing[0] != sharing[1]) {
        adjacency[sharing[0]].push_back(sharing[1]);
        adjacency[sharing[1]].push_back(sharing[0]);
      }
    base += triangles;
  }
  return adjacency;
}

std::vector<uint32_t> growCharts(const FlatTriangles& triangles, const std::vector<std::vector<uint32_t>>& adjacency,
                                 double coneAngleDegrees) {
  const size_t count = triangles.size();
  std::vector<glm::dvec3> normals(count);
  std::vector<double> areas(count);
  for (size_t t = 0; t < count; ++t) {
    const glm::dvec3 n = triangles.areaNormal(t);
    areas[t] = glm::length(n);
    normals[t] = areas[t] > 0.0 ? n / areas[t] : glm::dvec3(0.0);
  }
  std::vector<uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return areas[a] > areas[b]; });

  const double cosCone = std::cos(coneAngleDegrees * 3.14159265358979323846 / 180.0);
  std::vector<uint32_t> chart(count, kUnassigned);
  uint32_t charts = 0;
  for (uint32_t seed : order) {
    if (chart[seed] != kUnassigned || areas[seed] <= 0.0) continue;
    const uint32_t id = charts++;
    const glm::dvec3 axis = normals[seed];
    chart[seed] = id;
    std::deque<uint32_t> queue{seed};
    while (!queue.empty()) {
      const uint32_t t = queue.front();
      queue.pop_front();
      for (uint32_t n : adjacency[t]) {
        if (chart[n] != kUnassigned || areas[n] <= 0.0 || glm::dot(normals[n], axis) < cosCone) continue;
        chart[n] = id;
        queue.push_back(n);
      }
    }
  }
  // Zero-area triangles: adopt a neighbour's chart, spreading through
  // strips of them; whatever stays alone gets a chart of its own.
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t t = 0; t < count; ++t) {
      if (chart[t] != kUnassigned) continue;
      for (uint32_t n : adjacency[t])
        if (chart[n] != kUnassigned) {
          chart[t] = chart[n];
          changed = true;
          break;
        }
    }
  }
  for (size_t t = 0; t < count; ++t)
    if (chart[t] == kUnassigned) chart[t] = charts++;
  return chart;
}

}  // namespace sg::shadel
