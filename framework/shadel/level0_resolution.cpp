#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <utility>
#include <vector>

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

uint32_t screenRateLevel0Size(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const glm::mat4& world,
                              const glm::mat4& viewProjection, uint32_t width, uint32_t height, uint32_t level0,
                              double narrowShadels, double coverage) {
  if (chart.uvSet < 0 || width == 0 || height == 0) return 0;
  const glm::dmat4 toClip = glm::dmat4(viewProjection) * glm::dmat4(world);
  std::vector<std::pair<double, double>> densities;  // (pixels per UV unit squared, pixel area)
  double visibleArea = 0.0;
  for (const scene::Primitive& primitive : mesh.primitives) {
    const std::vector<glm::vec2>& uvs = primitive.uvs(chart.uvSet);
    if (uvs.empty()) continue;
    for (size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
      std::array<glm::dvec2, 3> pixel, uv;
      bool behind = false;
      glm::dvec2 lo(1e300), hi(-1e300);
      for (int k = 0; k < 3; ++k) {
        const uint32_t v = primitive.indices[i + size_t(k)];
        const glm::dvec4 clip = toClip * glm::dvec4(glm::dvec3(primitive.positions[v]), 1.0);
        if (clip.w <= 1e-9) behind = true;  // crosses the camera plane: its projection means nothing
        pixel[size_t(k)] = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * glm::dvec2(width, height);
        uv[size_t(k)] = glm::dvec2(uvs[v]);
        lo = glm::min(lo, pixel[size_t(k)]);
        hi = glm::max(hi, pixel[size_t(k)]);
      }
      if (behind || hi.x < 0.0 || hi.y < 0.0 || lo.x > width || lo.y > height) continue;
      auto area = [](const std::array<glm::dvec2, 3>& p) {
        return 0.5 * std::abs((p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y));
      };
      const double pixelArea = area(pixel), uvArea = area(uv);
      if (pixelArea <= 0.0) continue;
      const double longestEdge = std::max({glm::length(uv[1] - uv[0]), glm::length(uv[2] - uv[1]), glm::length(uv[0] - uv[2])});
      const bool narrow = longestEdge <= 0.0 || 2.0 * uvArea / longestEdge * level0 < narrowShadels;
      densities.emplace_back(!narrow ? 0.0 : uvArea > 0.0 ? pixelArea / uvArea : 1e300, pixelArea);
      visibleArea += pixelArea;
    }
  }
  if (densities.empty()) return 0;
  // The density that `coverage` of the projected area needs at most.
  std::sort(densities.begin(), densities.end());
  double covered = 0.0, needed = densities.back().first;
  for (const auto& [density, pixelArea] : densities) {
    covered += pixelArea;
    if (covered >= coverage * visibleArea) {
      needed = density;
      break;
    }
  }
  if (needed <= 0.0) return 0;
  const double size = std::sqrt(needed) / std::sqrt(2.0);
  const double log2Size = std::ceil(std::log2(std::max(size, 1.0)));
  return static_cast<uint32_t>(std::exp2(std::min(log2Size, 30.0)));
}

}  // namespace sg::shadel
