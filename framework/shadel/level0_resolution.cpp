#include <algorithm>
#include <bit>
#include <cmath>

#include <shadelgraph/shadel/chart_triangles.hpp>
#include <shadelgraph/shadel/level0_resolution.hpp>

namespace sg::shadel {
namespace {

double uvArea(const scene::Mesh& mesh, int uvSet) {
  double area = 0.0;
  for (const scene::Primitive& primitive : mesh.primitives) {
    const std::vector<glm::vec2>& uvs = primitive.uvs(uvSet);
    if (uvs.empty()) continue;
    for (size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
      const glm::dvec2 a(uvs[primitive.indices[i]]), b(uvs[primitive.indices[i + 1]]), c(uvs[primitive.indices[i + 2]]);
      area += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    }
  }
  return area;
}

}  // namespace

MeshTextureDensity meshTextureDensity(const scene::Scene& scene, const scene::Mesh& mesh) {
  MeshTextureDensity density;
  for (const scene::Primitive& primitive : mesh.primitives) {
    if (primitive.material < 0 || static_cast<size_t>(primitive.material) >= scene.materials.size()) continue;
    const scene::Material& material = scene.materials[static_cast<size_t>(primitive.material)];
    for (const scene::TextureRef& slot : material.textureSlots()) {
      const scene::TextureRef* ref = &slot;
      if (!ref->present() || static_cast<size_t>(ref->texture) >= scene.textures.size()) continue;
      const scene::Texture& texture = scene.textures[static_cast<size_t>(ref->texture)];
      // KHR_texture_transform scales how many texels a UV unit spans.
      const float scale = std::max(std::abs(ref->transform.scale.x), std::abs(ref->transform.scale.y));
      const auto resolution = static_cast<uint32_t>(std::max(texture.width, texture.height) * std::max(scale, 1e-3f));
      if (resolution > density.resolution) density = {resolution, ref->texCoord};
    }
  }
  return density;
}

uint32_t chooseLevel0Size(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const MeshTextureDensity& texture,
                          const Level0Options& options) {
  const double chartArea = chart.uvSet >= 0 ? std::max(uvArea(mesh, chart.uvSet), 1e-6) : 1.0;
  double size = std::sqrt(options.texelsPerTriangle * static_cast<double>(mesh.triangleCount()) / chartArea);
  if (texture.resolution > 0) {
    const double textureArea = uvArea(mesh, texture.uvSet);
    const double ratio = textureArea > 0.0 ? std::sqrt(textureArea / chartArea) : 1.0;
    size = std::max(size, texture.resolution * ratio);
  }
  const double log2Size = std::round(std::log2(std::max(size, 1.0)));
  const auto rounded = static_cast<uint32_t>(std::exp2(std::min(log2Size, 30.0)));
  return std::clamp(rounded, std::bit_ceil(options.minSize), std::bit_floor(options.maxSize));
}

}  // namespace sg::shadel
