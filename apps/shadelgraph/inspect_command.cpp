// shadelgraph inspect <scene>: per mesh, triangles, UV sets, the shading-chart
// verdict with its counts, and materials; per object, decoupled or forward and
// why (as render would choose at load); the animations. No device needed.
#include <cstdio>
#include <set>

#include <decoupled/shading_choice.hpp>
#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/chart_density.hpp>

#include "commands.hpp"
#include "scene_source.hpp"

namespace sg::app {

void addInspectCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("inspect", "Print meshes, UV sets, shading-chart verdicts and materials of a scene");
  static std::string path;
  cmd->add_option("scene", path, "a .gltf/.glb/.json scene (default: the built-in scene)");
  static std::string mode;
  cmd->add_option("--mode", mode, "shading of every object for the per-object list (default: each object's own)")
      ->check(CLI::IsMember({"forward", "decoupled", "auto"}));
  cmd->callback([] {
    const scene::Scene s = loadSceneArgument(path).scene;
    std::printf("%zu meshes, %zu instances, %zu materials, %zu textures, %zu lights, %zu cameras, %zu triangles drawn\n",
                s.meshes.size(), s.instances.size(), s.materials.size(), s.textures.size(), s.lights.size(),
                s.cameras.size(), scene::instancedTriangleCount(s));
    for (const auto& mesh : s.meshes) {
      bool uv0 = false, uv1 = false;
      std::set<int> materials;
      for (const auto& p : mesh.primitives) {
        uv0 |= !p.uv0.empty();
        uv1 |= !p.uv1.empty();
        materials.insert(p.material);
      }
      const auto verdict = scene::chooseShadingChart(mesh);
      std::printf("mesh '%s': %zu triangles, %zu primitives, UV sets:%s%s%s\n", mesh.name.c_str(), mesh.triangleCount(),
                  mesh.primitives.size(), uv0 ? " TEXCOORD_0" : "", uv1 ? " TEXCOORD_1" : "",
                  uv0 || uv1 ? "" : " none");
      std::printf("  chart: %s", verdict.unique ? "unique" : "not unique");
      if (verdict.uvSet >= 0)
        std::printf(" (TEXCOORD_%d: %zu overlapping pairs%s, %zu overlapping triangles, %zu out-of-range UVs, "
                    "%zu zero-UV-area triangles)",
                    verdict.uvSet, verdict.overlappingPairs, verdict.countsTruncated ? "+" : "",
                    verdict.overlappingTriangles, verdict.outOfRangeUvs, verdict.zeroAreaTriangles);
      if (!verdict.reason.empty()) std::printf(" - %s", verdict.reason.c_str());
      if (verdict.unique) {
        // What decoupled shading makes of a unique chart: even enough, or automatic chart / forward.
        const shadel::ChartDensity density = shadel::chartDensity(mesh, verdict.uvSet);
        std::printf("\n  density: %s%s", density.describe().c_str(),
                    density.even ? "" : " (uneven: decoupled shading charts it anew, auto mode shades it forward)");
      }
      size_t closed = 0;
      for (const auto& p : mesh.primitives) closed += p.closedSurface ? 1 : 0;
      // Closed surfaces have their back faces culled while seen from outside, double-sided or not.
      std::printf("\n  closed surfaces: %zu of %zu primitives", closed, mesh.primitives.size());
      std::printf("\n  materials:");
      for (int m : materials) std::printf(" '%s'", s.materials[size_t(m)].name.c_str());
      std::printf("\n");
    }
    // Per object, what render chooses at load (an object may still go forward
    // at run time: render prints those after its frames).
    scene::Scene charted = s;  // chooseShading charts meshes anew where decoupled shading needs it
    const auto override = mode.empty() ? std::nullopt : scene::parseShadingMode(mode);
    for (const auto& choice : plugins::chooseShading(charted, override))
      std::fputs(plugins::shadingReportLines(s.instances[choice.instance].name, plugins::shadingReport(choice)).c_str(),
                 stdout);
    for (const auto& animation : s.animations) {
      const char* paths[] = {"translation", "rotation", "scale", "weights"};
      const char* interpolations[] = {"STEP", "LINEAR", "CUBICSPLINE"};
      std::printf("animation '%s': %.3f s, %zu channels:", animation.name.c_str(), double(animation.duration()),
                  animation.channels.size());
      for (size_t c = 0; c < animation.channels.size(); ++c) {
        const auto& channel = animation.channels[c];
        std::printf("%s '%s' %s %s", c ? "," : "", s.nodes[size_t(channel.node)].name.c_str(), paths[int(channel.path)],
                    interpolations[int(animation.samplers[size_t(channel.sampler)].interpolation)]);
      }
      std::printf("\n");
    }
    for (const auto& w : s.warnings) std::printf("warning: %s\n", w.c_str());
  });
}

}  // namespace sg::app
