#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <vector>

#include <shadelgraph/scene/uv_chart.hpp>

namespace sg::scene {
namespace {

using Point = glm::dvec2;
using Triangle = std::array<Point, 3>;

double signedArea(const Triangle& t) {
  return 0.5 * ((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y));
}

// Separating-axis test on the six edge normals: true when no axis separates
// the triangles, i.e. their interiors may intersect (touching counts as
// separated).
bool interiorsMayIntersect(const Triangle& a, const Triangle& b) {
  for (const Triangle* edges : {&a, &b}) {
    for (int e = 0; e < 3; ++e) {
      const Point d = (*edges)[static_cast<size_t>((e + 1) % 3)] - (*edges)[static_cast<size_t>(e)];
      const Point axis{-d.y, d.x};
      double minA = HUGE_VAL, maxA = -HUGE_VAL, minB = HUGE_VAL, maxB = -HUGE_VAL;
      for (size_t k = 0; k < 3; ++k) {
        const double pa = glm::dot(a[k], axis), pb = glm::dot(b[k], axis);
        minA = std::min(minA, pa), maxA = std::max(maxA, pa);
        minB = std::min(minB, pb), maxB = std::max(maxB, pb);
      }
      if (std::min(maxA, maxB) - std::max(minA, minB) <= 0.0) return false;
    }
  }
  return true;
}

// Area of a ∩ b: a clipped by b's three edges (Sutherland–Hodgman).
double intersectionArea(const Triangle& a, Triangle b) {
  if (signedArea(b) < 0.0) std::swap(b[1], b[2]);  // counter-clockwise: inside is left of every edge
  std::vector<Point> polygon(a.begin(), a.end()), clipped;
  for (size_t e = 0; e < 3 && !polygon.empty(); ++e) {
    const Point p = b[e], q = b[(e + 1) % 3];
    const auto side = [&](const Point& x) { return (q.x - p.x) * (x.y - p.y) - (q.y - p.y) * (x.x - p.x); };
    clipped.clear();
    for (size_t i = 0; i < polygon.size(); ++i) {
      const Point& current = polygon[i];
      const Point& next = polygon[(i + 1) % polygon.size()];
      const double sc = side(current), sn = side(next);
      if (sc >= 0.0) clipped.push_back(current);
      if ((sc >= 0.0) != (sn >= 0.0)) clipped.push_back(current + (next - current) * (sc / (sc - sn)));
    }
    std::swap(polygon, clipped);
  }
  double area = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point& u = polygon[i];
    const Point& v = polygon[(i + 1) % polygon.size()];
    area += u.x * v.y - v.x * u.y;
  }
  return std::abs(area) * 0.5;
}

// One primitive's share of the chart.
struct Part {
  std::span<const glm::vec2> uvs;
  std::span<const uint32_t> indices;
  // Empty when the shape may change (skinned or morphed): then no triangle counts as degenerate.
  std::span<const glm::vec3> positions;
};

// Triangles of zero surface area cover no pixel (CAD meshes are full of
// them): the chart need not hold them. Zero relative to the part's size.
std::vector<bool> degenerateTriangles(const Part& part, double relativeEpsilon) {
  std::vector<bool> degenerate(part.indices.size() / 3, false);
  if (part.positions.empty()) return degenerate;
  glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (const uint32_t index : part.indices) {
    lo = glm::min(lo, glm::dvec3(part.positions[index]));
    hi = glm::max(hi, glm::dvec3(part.positions[index]));
  }
  const glm::dvec3 extent = hi - lo;
  const double scale = glm::dot(extent, extent);  // squared diagonal
  for (size_t t = 0; t < degenerate.size(); ++t) {
    const glm::dvec3 a(part.positions[part.indices[3 * t]]), b(part.positions[part.indices[3 * t + 1]]),
        c(part.positions[part.indices[3 * t + 2]]);
    degenerate[t] = 0.5 * glm::length(glm::cross(b - a, c - a)) <= relativeEpsilon * scale;
  }
  return degenerate;
}

std::span<const glm::vec3> fixedPositions(const Primitive& primitive) {
  if (primitive.skinned() || primitive.morphed()) return {};
  return primitive.positions;
}

const char* setName(int uvSet) { return uvSet == 1 ? "TEXCOORD_1" : "TEXCOORD_0"; }

ChartVerdict analyze(std::span<const Part> parts, int uvSet, const UvChartOptions& options) {
  ChartVerdict verdict;
  verdict.uvSet = uvSet;
  const std::string name = setName(uvSet);

  // The tile: the unit square holding the center of the UVs' bounding box.
  glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (const Part& part : parts)
    for (uint32_t index : part.indices) {
      lo = glm::min(lo, glm::dvec2(part.uvs[index]));
      hi = glm::max(hi, glm::dvec2(part.uvs[index]));
    }
  std::vector<std::vector<bool>> degenerate;
  for (const Part& part : parts) {
    degenerate.push_back(degenerateTriangles(part, options.zeroSurfaceAreaEpsilon));
    verdict.degenerateTriangles += size_t(std::count(degenerate.back().begin(), degenerate.back().end(), true));
    verdict.triangles += part.indices.size() / 3;
  }
  verdict.triangles -= verdict.degenerateTriangles;
  if (verdict.triangles == 0) {
    verdict.reason = name + ": no triangles";
    return verdict;
  }
  const glm::dvec2 tile = glm::floor((lo + hi) * 0.5);
  verdict.tileOffset = glm::vec2(tile);

  // Out-of-range vertices (each counted once) and the triangles, shifted into the tile.
  std::vector<Triangle> triangles;
  triangles.reserve(verdict.triangles);
  double chartArea = 0.0;
  for (size_t p = 0; p < parts.size(); ++p) {
    const Part& part = parts[p];
    std::vector<bool> seen(part.uvs.size(), false);
    for (uint32_t index : part.indices) {
      if (seen[index]) continue;
      seen[index] = true;
      const glm::dvec2 uv = glm::dvec2(part.uvs[index]) - tile;
      if (uv.x < -options.rangeEpsilon || uv.y < -options.rangeEpsilon || uv.x > 1.0 + options.rangeEpsilon ||
          uv.y > 1.0 + options.rangeEpsilon)
        ++verdict.outOfRangeUvs;
    }
    for (size_t corner = 0; corner + 2 < part.indices.size(); corner += 3) {
      if (degenerate[p][corner / 3]) continue;  // covers no pixel
      Triangle t;
      for (size_t k = 0; k < 3; ++k) t[k] = glm::dvec2(part.uvs[part.indices[corner + k]]) - tile;
      const double area = std::abs(signedArea(t));
      chartArea += area;
      if (area <= options.zeroAreaEpsilon) {
        ++verdict.zeroAreaTriangles;
        continue;  // no interior: cannot overlap anything
      }
      triangles.push_back(t);
    }
  }

  // Uniform grid over the triangles' bounds, about one triangle per cell.
  const size_t count = triangles.size();
  glm::dvec2 gridLo(HUGE_VAL), gridHi(-HUGE_VAL);
  for (const Triangle& t : triangles)
    for (const Point& p : t) gridLo = glm::min(gridLo, p), gridHi = glm::max(gridHi, p);
  const int cellsPerSide = std::clamp(static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)))), 1, 1024);
  const glm::dvec2 cellSize = glm::max((gridHi - gridLo) / static_cast<double>(cellsPerSide), glm::dvec2(1e-12));
  const auto cellOf = [&](const Point& p) {
    const glm::ivec2 cell(glm::floor((p - gridLo) / cellSize));
    return glm::clamp(cell, glm::ivec2(0), glm::ivec2(cellsPerSide - 1));
  };
  std::vector<glm::ivec2> cellMin(count), cellMax(count);
  std::vector<size_t> cellStart(static_cast<size_t>(cellsPerSide) * static_cast<size_t>(cellsPerSide) + 1, 0);
  const auto cellIndex = [&](int x, int y) { return static_cast<size_t>(y) * static_cast<size_t>(cellsPerSide) + static_cast<size_t>(x); };
  for (size_t i = 0; i < count; ++i) {
    const Triangle& t = triangles[i];
    cellMin[i] = cellOf(glm::min(glm::min(t[0], t[1]), t[2]));
    cellMax[i] = cellOf(glm::max(glm::max(t[0], t[1]), t[2]));
    for (int y = cellMin[i].y; y <= cellMax[i].y; ++y)
      for (int x = cellMin[i].x; x <= cellMax[i].x; ++x) ++cellStart[cellIndex(x, y) + 1];
  }
  for (size_t c = 1; c < cellStart.size(); ++c) cellStart[c] += cellStart[c - 1];
  std::vector<uint32_t> cellTriangles(cellStart.back());
  std::vector<size_t> fill(cellStart.begin(), cellStart.end() - 1);
  for (size_t i = 0; i < count; ++i)
    for (int y = cellMin[i].y; y <= cellMax[i].y; ++y)
      for (int x = cellMin[i].x; x <= cellMax[i].x; ++x) cellTriangles[fill[cellIndex(x, y)]++] = static_cast<uint32_t>(i);

  std::vector<bool> overlapping(count, false);
  for (int y = 0; y < cellsPerSide && !verdict.countsTruncated; ++y)
    for (int x = 0; x < cellsPerSide && !verdict.countsTruncated; ++x) {
      const size_t begin = cellStart[cellIndex(x, y)], end = cellStart[cellIndex(x, y) + 1];
      for (size_t ia = begin; ia < end && !verdict.countsTruncated; ++ia)
        for (size_t ib = ia + 1; ib < end; ++ib) {
          const uint32_t a = cellTriangles[ia], b = cellTriangles[ib];
          // Test each pair once: in the first cell both triangles' boxes cover.
          if (glm::max(cellMin[a], cellMin[b]) != glm::ivec2(x, y)) continue;
          if (!interiorsMayIntersect(triangles[a], triangles[b])) continue;
          if (intersectionArea(triangles[a], triangles[b]) <= options.overlapAreaEpsilon) continue;
          ++verdict.overlappingPairs;
          overlapping[a] = overlapping[b] = true;
          if (verdict.overlappingPairs >= options.maxOverlappingPairs) {
            verdict.countsTruncated = true;
            break;
          }
        }
    }
  verdict.overlappingTriangles = static_cast<size_t>(std::count(overlapping.begin(), overlapping.end(), true));

  std::vector<std::string> problems;
  if (verdict.overlappingPairs)
    problems.push_back(std::to_string(verdict.overlappingPairs) + (verdict.countsTruncated ? "+" : "") +
                       " overlapping triangle pairs (" + std::to_string(verdict.overlappingTriangles) + " triangles)");
  if (verdict.outOfRangeUvs)
    problems.push_back(std::to_string(verdict.outOfRangeUvs) + " UVs outside one unit tile");
  if (static_cast<double>(verdict.zeroAreaTriangles) > options.maxZeroAreaFraction * static_cast<double>(verdict.triangles))
    problems.push_back(std::to_string(verdict.zeroAreaTriangles) + " of " + std::to_string(verdict.triangles) +
                       " triangles have zero UV area");
  if (!(chartArea > options.zeroAreaEpsilon)) problems.push_back("the chart has no area");

  verdict.unique = problems.empty();
  if (verdict.unique) {
    verdict.reason = name + ": unique chart";
    if (verdict.zeroAreaTriangles) verdict.reason += ", " + std::to_string(verdict.zeroAreaTriangles) + " zero-area triangles";
    if (verdict.degenerateTriangles)
      verdict.reason += ", " + std::to_string(verdict.degenerateTriangles) + " triangles of zero surface area ignored";
    if (tile != glm::dvec2(0.0))
      verdict.reason += ", in tile (" + std::to_string(static_cast<int>(tile.x)) + ", " +
                        std::to_string(static_cast<int>(tile.y)) + ")";
  } else {
    verdict.reason = name + ":";
    for (size_t i = 0; i < problems.size(); ++i) verdict.reason += (i ? ", " : " ") + problems[i];
  }
  return verdict;
}

ChartVerdict missing(int uvSet, const std::string& what) {
  ChartVerdict verdict;
  verdict.uvSet = -1;
  verdict.reason = what + " has no " + setName(uvSet);
  return verdict;
}

template <class Analyze, class Has>
ChartVerdict choose(Analyze analyzeSet, Has hasSet, const std::string& what) {
  if (!hasSet(0) && !hasSet(1)) {
    ChartVerdict verdict;
    verdict.reason = what + " has no TEXCOORD_0 or TEXCOORD_1";
    return verdict;
  }
  std::string rejected;
  if (hasSet(1)) {
    ChartVerdict second = analyzeSet(1);
    if (second.unique || !hasSet(0)) return second;
    rejected = second.reason + "; ";
  }
  ChartVerdict first = analyzeSet(0);
  first.reason = rejected + first.reason;
  return first;
}

}  // namespace

ChartVerdict analyzeUvSet(const Primitive& primitive, int uvSet, const UvChartOptions& options) {
  if (primitive.uvs(uvSet).empty()) return missing(uvSet, "the primitive");
  const Part part{primitive.uvs(uvSet), primitive.indices, fixedPositions(primitive)};
  return analyze({&part, 1}, uvSet, options);
}

ChartVerdict analyzeUvSet(const Mesh& mesh, int uvSet, const UvChartOptions& options) {
  std::vector<Part> parts;
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const Primitive& primitive = mesh.primitives[p];
    if (primitive.uvs(uvSet).empty()) return missing(uvSet, "primitive " + std::to_string(p));
    parts.push_back({primitive.uvs(uvSet), primitive.indices, fixedPositions(primitive)});
  }
  return analyze(parts, uvSet, options);
}

ChartVerdict chooseShadingChart(const Primitive& primitive, const UvChartOptions& options) {
  return choose([&](int set) { return analyzeUvSet(primitive, set, options); },
                [&](int set) { return !primitive.uvs(set).empty(); }, "the primitive");
}

ChartVerdict chooseShadingChart(const Mesh& mesh, const UvChartOptions& options) {
  const auto hasSet = [&](int set) {
    return !mesh.primitives.empty() && std::all_of(mesh.primitives.begin(), mesh.primitives.end(),
                                                   [set](const Primitive& p) { return !p.uvs(set).empty(); });
  };
  return choose([&](int set) { return analyzeUvSet(mesh, set, options); }, hasSet, "the mesh");
}

}  // namespace sg::scene
