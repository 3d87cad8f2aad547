#include "shading_choice.hpp"

#include <algorithm>
#include <bit>
#include <map>
#include <utility>

#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/auto_chart.hpp>
#include <shadelgraph/shadel/chart_density.hpp>
#include <shadelgraph/shadel/level0_resolution.hpp>

namespace sg::plugins {
namespace {

// The chart verdict of one primitive (alone), after an automatic chart when
// the object is in mode decoupled and its UVs are no unique chart; may replace
// the primitive in `scene` by its charted copy.
scene::ChartVerdict primitiveVerdict(scene::Scene& scene, scene::Mesh& mesh, size_t p, scene::ShadingMode mode) {
  const scene::Mesh alone = mesh.primitives.size() == 1 ? scene::Mesh{} : primitiveMesh(mesh, p);
  const scene::Mesh& subject = mesh.primitives.size() == 1 ? mesh : alone;
  scene::ChartVerdict verdict = scene::chooseShadingChart(subject);
  bool uneven = false;
  if (verdict.unique) {
    // A unique chart that starves part of the surface of shadels shades it
    // coarser than the screen asks at every level (chart_density.hpp).
    const shadel::ChartDensity density = shadel::chartDensity(subject, verdict.uvSet);
    if (!density.even) {
      uneven = true;
      verdict.unique = false;
      verdict.reason = "TEXCOORD_" + std::to_string(verdict.uvSet) + " is unique but uneven: " + density.describe();
    }
  }
  if (verdict.unique || mode != scene::ShadingMode::Decoupled) return verdict;
  // Gutters measured at the resolution the textures suggest (what level 0 will be near).
  const auto texture = shadel::meshTextureDensity(scene, subject);
  const uint32_t resolution = std::max(texture.resolution > 0 ? std::bit_ceil(texture.resolution) : 0u, 256u);
  auto charted = shadel::autoChartMesh(subject, {.resolution = resolution, .replaceUv1 = true});
  if (!charted.ok()) {
    verdict.reason += "; automatic chart failed: " + charted.error;
    return verdict;
  }
  mesh.primitives[p] = std::move(charted.mesh.primitives[0]);
  const std::string refused = verdict.reason;
  verdict = scene::chooseShadingChart(mesh.primitives[p]);
  const std::string still = verdict.unique ? "" : ", not unique either: " + verdict.reason;  // what the chart check found
  verdict.reason = "automatic chart (" + std::to_string(charted.stats.charts) + " charts" +
                   (uneven ? "; " + refused : "") + still + ")";
  return verdict;
}

}  // namespace

scene::Mesh primitiveMesh(const scene::Mesh& mesh, size_t p) {
  if (mesh.primitives.size() == 1) return mesh;
  return {.name = mesh.name, .primitives = {mesh.primitives[p]}, .bounds = mesh.primitives[p].bounds,
          .weights = mesh.weights};
}

std::string alphaModeRefusal(const scene::Material& material) {
  if (material.alphaMode != scene::AlphaMode::Blend) return "";
  return "alpha-blended material '" + material.name + "' (what is behind shows through: shaded forward)";
}

std::string objectReason(const std::vector<PrimitiveChoice>& primitives) {
  if (primitives.empty()) return "no primitives";
  const bool same = std::all_of(primitives.begin(), primitives.end(),
                                [&](const PrimitiveChoice& c) { return c.reason == primitives[0].reason; });
  if (primitives.size() == 1) return primitives[0].reason;
  if (same) return std::to_string(primitives.size()) + " primitives, each: " + primitives[0].reason;
  std::string reason;
  for (size_t p = 0; p < primitives.size(); ++p)
    reason += (p ? "; primitive " : "primitive ") + std::to_string(p) + ": " + primitives[p].reason;
  return reason;
}

std::vector<ShadingChoice> chooseShading(scene::Scene& scene, std::optional<scene::ShadingMode> override) {
  std::vector<ShadingChoice> choices;
  std::map<std::pair<int, size_t>, scene::ChartVerdict> verdicts;  // by mesh and primitive, after any automatic chart
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    auto& instance = scene.instances[i];
    if (override) instance.shading = *override;  // the renderer starts from the instances' modes
    const auto mode = instance.shading;
    ShadingChoice choice{.instance = i, .automatic = mode == scene::ShadingMode::Auto};
    auto& mesh = scene.meshes[size_t(instance.mesh)];
    bool all = true, any = false;  // every primitive decoupled shading takes is eligible; there is one
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      PrimitiveChoice primitive;
      primitive.reason = alphaModeRefusal(scene.materials[size_t(mesh.primitives[p].material)]);
      if (primitive.reason.empty()) {
        auto it = verdicts.find({instance.mesh, p});
        if (it == verdicts.end()) it = verdicts.emplace(std::pair{instance.mesh, p}, primitiveVerdict(scene, mesh, p, mode)).first;
        const scene::ChartVerdict& verdict = it->second;
        // From the primitive, not from this call: a scene chosen for again
        // (the viewer) already holds the charted copy.
        primitive.automaticChart = mesh.primitives[p].automaticChart && verdict.unique && verdict.uvSet == 1;
        primitive.eligible = verdict.unique;
        primitive.uvSet = verdict.uvSet;
        primitive.tileOffset = verdict.tileOffset;
        primitive.reason = verdict.unique ? (verdict.reason.empty() ? "unique TEXCOORD_" + std::to_string(verdict.uvSet)
                                                                    : verdict.reason)
                                          : "no unique chart: " + verdict.reason;
        all = all && verdict.unique;
        any = true;
      }
      choice.primitives.push_back(std::move(primitive));
    }
    choice.eligible = all && any;
    choice.decoupled = choice.eligible && mode != scene::ShadingMode::Forward;
    choice.reason = mode == scene::ShadingMode::Forward && choice.eligible ? "forward by request"
                                                                           : objectReason(choice.primitives);
    choices.push_back(std::move(choice));
  }
  return choices;
}

ShadingReport shadingReport(const ShadingChoice& choice) {
  ShadingReport report{.shading = choice.decoupled ? "decoupled" : "forward", .reason = choice.reason};
  if (choice.primitives.size() > 1)
    for (const auto& primitive : choice.primitives)
      report.primitives.push_back(
          {.shading = choice.decoupled && primitive.eligible ? "decoupled" : "forward", .reason = primitive.reason});
  return report;
}

std::string shadingReportLines(const std::string& name, const ShadingReport& report) {
  std::string lines = "object '" + name + "': " + report.shading + " (" + report.reason + ")\n";
  for (size_t p = 0; p < report.primitives.size(); ++p)
    lines += "  primitive " + std::to_string(p) + ": " + report.primitives[p].shading + " (" +
             report.primitives[p].reason + ")\n";
  return lines;
}

}  // namespace sg::plugins
