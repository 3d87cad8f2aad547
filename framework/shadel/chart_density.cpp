#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include <shadelgraph/shadel/chart_density.hpp>

namespace sg::shadel {

std::string ChartDensity::describe() const {
  if (std::isinf(linearSpread)) return "part of the surface has no UV area";
  char text[160];
  std::snprintf(text, sizeof text, "its sparsest tenth is shaded %.3gx coarser per side than the mean", linearSpread);
  return text;
}

ChartDensity chartDensity(const scene::Mesh& mesh, int uvSet, const ChartDensityOptions& options) {
  ChartDensity result;
  std::vector<std::pair<double, double>> triangles;  // (UV area / world area, world area)
  for (const scene::Primitive& primitive : mesh.primitives) {
    const std::vector<glm::vec2>& uvs = primitive.uvs(uvSet);
    if (uvs.empty()) continue;
    for (size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
      const uint32_t a = primitive.indices[i], b = primitive.indices[i + 1], c = primitive.indices[i + 2];
      const glm::dvec3 pa(primitive.positions[a]), pb(primitive.positions[b]), pc(primitive.positions[c]);
      const double world = 0.5 * glm::length(glm::cross(pb - pa, pc - pa));
      const glm::dvec2 ua(uvs[a]), ub(uvs[b]), uc(uvs[c]);
      const double uv = 0.5 * std::abs((ub.x - ua.x) * (uc.y - ua.y) - (uc.x - ua.x) * (ub.y - ua.y));
      if (!(world > 0.0) || !std::isfinite(world) || !std::isfinite(uv)) continue;
      result.worldArea += world;
      result.uvArea += uv;
      triangles.emplace_back(uv / world, world);
    }
  }
  if (!(result.worldArea > 0.0) || !(result.uvArea > 0.0)) return result;
  result.meanDensity = result.uvArea / result.worldArea;
  std::sort(triangles.begin(), triangles.end());
  const double sparseArea = options.sparseFraction * result.worldArea;
  double accumulated = 0.0;
  result.sparseDensity = triangles.back().first;
  for (const auto& [density, world] : triangles) {
    accumulated += world;
    if (accumulated >= sparseArea) {
      result.sparseDensity = density;
      break;
    }
  }
  result.linearSpread = result.sparseDensity > 0.0 ? std::sqrt(result.meanDensity / result.sparseDensity)
                                                   : std::numeric_limits<double>::infinity();
  result.even = result.linearSpread <= options.maxLinearSpread;
  return result;
}

}  // namespace sg::shadel
