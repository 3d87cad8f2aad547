#include <algorithm>
#include <cmath>

#include <shadelgraph/shadel/chart_density.hpp>
#include <shadelgraph/shadel/unmipmapped_minification.hpp>

namespace sg::shadel {

UnmipmappedTexels unmipmappedTexels(const scene::Scene& scene, const scene::Mesh& mesh) {
  UnmipmappedTexels finest;
  for (const scene::Primitive& primitive : mesh.primitives) {
    if (primitive.material < 0 || static_cast<size_t>(primitive.material) >= scene.materials.size()) continue;
    for (const scene::TextureRef& ref : scene.materials[static_cast<size_t>(primitive.material)].textureSlots()) {
      if (!ref.present() || static_cast<size_t>(ref.texture) >= scene.textures.size()) continue;
      const scene::Texture& texture = scene.textures[static_cast<size_t>(ref.texture)];
      const auto sampler = static_cast<size_t>(texture.sampler);
      if (sampler >= scene.samplers.size() || scene.samplers[sampler].mipmapMode != scene::MipmapMode::None) continue;
      const ChartDensity density = chartDensity(mesh, ref.texCoord);  // UV area per surface area
      const auto scale = static_cast<double>(std::max(std::abs(ref.transform.scale.x), std::abs(ref.transform.scale.y)));
      const double texels = std::max(texture.width, texture.height) * scale * std::sqrt(density.meanDensity);
      if (texels > finest.texelsPerUnit) finest = {texels, texture.name};
    }
  }
  return finest;
}

double unmipmappedTexelsPerPixel(const UnmipmappedTexels& texels, double worldScale, double distance,
                                 double pixelsPerUnitAtUnitDistance) {
  if (texels.texelsPerUnit <= 0.0 || worldScale <= 0.0 || distance <= 0.0 || pixelsPerUnitAtUnitDistance <= 0.0)
    return 0.0;
  const double pixelsPerWorldUnit = pixelsPerUnitAtUnitDistance / distance;
  return texels.texelsPerUnit / worldScale / pixelsPerWorldUnit;
}

}  // namespace sg::shadel
