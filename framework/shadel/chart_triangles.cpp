#include <cmath>
#include <stdexcept>
#include <string>

#include <shadelgraph/shadel/chart_triangles.hpp>

namespace sg::shadel {

double ChartTriangles::area(size_t triangle) const {
  const auto& t = uv[triangle];
  return 0.5 * std::abs((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y));
}

double ChartTriangles::totalArea() const {
  double total = 0.0;
  for (size_t t = 0; t < uv.size(); ++t) total += area(t);
  return total;
}

ChartTriangles chartTriangles(const scene::Mesh& mesh, int uvSet, glm::vec2 tileOffset) {
  ChartTriangles chart;
  const glm::dvec2 offset(tileOffset);
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    const scene::Primitive& primitive = mesh.primitives[p];
    const std::vector<glm::vec2>& uvs = primitive.uvs(uvSet);
    if ((uvSet != 0 && uvSet != 1) || (uvs.empty() && primitive.triangleCount() > 0))
      throw std::invalid_argument("primitive " + std::to_string(p) + " has no TEXCOORD_" + std::to_string(uvSet));
    chart.primitiveTriangleBase.push_back(static_cast<uint32_t>(chart.uv.size()));
    for (size_t corner = 0; corner + 2 < primitive.indices.size(); corner += 3) {
      std::array<glm::dvec2, 3> t;
      for (size_t k = 0; k < 3; ++k) t[k] = glm::dvec2(uvs.at(primitive.indices[corner + k])) - offset;
      chart.uv.push_back(t);
    }
  }
  return chart;
}

}  // namespace sg::shadel
