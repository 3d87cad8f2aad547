#include "shading_choice.hpp"

#include <algorithm>
#include <bit>
#include <map>

#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/auto_chart.hpp>
#include <shadelgraph/shadel/chart_density.hpp>
#include <shadelgraph/shadel/level0_resolution.hpp>

namespace sg::plugins {

std::vector<ShadingChoice> chooseShading(scene::Scene& scene, std::optional<scene::ShadingMode> override) {
  std::vector<ShadingChoice> choices;
  std::map<int, scene::ChartVerdict> verdicts;  // by mesh, after any automatic chart
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    auto& instance = scene.instances[i];
    if (override) instance.shading = *override;  // the renderer starts from the instances' modes
    const auto mode = instance.shading;
    ShadingChoice choice{.instance = i, .automatic = mode == scene::ShadingMode::Auto};
    auto& mesh = scene.meshes[size_t(instance.mesh)];
    if (mesh.primitives.size() != 1) {
      choice.reason = std::to_string(mesh.primitives.size()) + " primitives (decoupled shading takes single-primitive meshes so far)";
    } else if (scene.materials[size_t(mesh.primitives[0].material)].alphaMode != scene::AlphaMode::Opaque) {
      choice.reason = "alpha-masked or blended material (decoupled shading takes opaque materials so far)";
    } else {
      auto it = verdicts.find(instance.mesh);
      if (it == verdicts.end()) {
        scene::ChartVerdict verdict = scene::chooseShadingChart(mesh);
        bool uneven = false;
        if (verdict.unique) {
          // A unique chart that starves part of the surface of shadels shades it
          // coarser than the screen asks at every level (chart_density.hpp).
          const shadel::ChartDensity density = shadel::chartDensity(mesh, verdict.uvSet);
          if (!density.even) {
            uneven = true;
            verdict.unique = false;
            verdict.reason = "TEXCOORD_" + std::to_string(verdict.uvSet) + " is unique but uneven: " + density.describe();
          }
        }
        if (!verdict.unique && mode == scene::ShadingMode::Decoupled) {
          // Gutters measured at the resolution the mesh's textures suggest (what level 0 will be near).
          const auto texture = shadel::meshTextureDensity(scene, mesh);
          const uint32_t resolution = std::max(texture.resolution > 0 ? std::bit_ceil(texture.resolution) : 0u, 256u);
          auto charted = shadel::autoChartMesh(mesh, {.resolution = resolution, .replaceUv1 = true});
          if (charted.ok()) {
            mesh = std::move(charted.mesh);
            const std::string refused = verdict.reason;
            verdict = scene::chooseShadingChart(mesh);
            verdict.reason = "automatic chart (" + std::to_string(charted.stats.charts) + " charts" +
                             (uneven ? "; " + refused : "") + ")";
          } else {
            verdict.reason += "; automatic chart failed: " + charted.error;
          }
        }
        it = verdicts.emplace(instance.mesh, verdict).first;
      }
      const auto& verdict = it->second;
      choice.eligible = verdict.unique;
      choice.decoupled = verdict.unique && mode != scene::ShadingMode::Forward;
      choice.uvSet = verdict.uvSet;
      choice.tileOffset = verdict.tileOffset;
      choice.reason = verdict.unique ? (verdict.reason.empty() ? "unique TEXCOORD_" + std::to_string(verdict.uvSet)
                                                               : verdict.reason)
                                     : "no unique chart: " + verdict.reason;
      if (mode == scene::ShadingMode::Forward && verdict.unique) choice.reason = "forward by request";
    }
    choices.push_back(std::move(choice));
  }
  return choices;
}

}  // namespace sg::plugins
