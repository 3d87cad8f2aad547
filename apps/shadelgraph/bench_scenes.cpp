#include "bench_scenes.hpp"

#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <builtin_plugins.hpp>
#include <decoupled/decoupled_package.hpp>
#include <shadelgraph/render/renderer.hpp>

#include "bench_materials.hpp"
#include "command_options.hpp"
#include "option_checks.hpp"
#include "output_file.hpp"
#include "scene_source.hpp"

namespace sg::app {
namespace {

struct RatioConfig {
  std::string name;
  bool decoupled = false;
  bool asBefore = false;  // without occlusion culling, as before issue 14
};

const std::vector<RatioConfig> kConfigs{{"forward", false, false},
                                        {"decoupled", true, false},
                                        {"forward as before", false, true},
                                        {"decoupled as before", true, true}};

struct Session {
  scene::Scene scene;
  std::shared_ptr<plugins::DecoupledShading> decoupled;
  std::unique_ptr<render::Renderer> renderer;
  std::vector<double> frameMs;
  std::map<std::string, std::vector<double>> passMs;
};

// The first scene's camera: its first camera path at time 0 when it has one
// (framed for that scene's bounds), else the renderer's default view.
scene::Camera baselineCamera(const LoadedScene& loaded, const render::Renderer& renderer, uint32_t width,
                             uint32_t height) {
  if (loaded.cameraPaths.empty()) return renderer.camera({.width = width, .height = height});
  const auto pose = scene::evaluatePose(loaded.cameraPaths.front(), 0.0f);
  return scene::poseCamera(pose, scene::worldBounds(loaded.scene));
}

nlohmann::json benchSize(gpu::Device& device, const std::vector<LoadedScene>& loaded,
                         const std::vector<std::string>& names, uint32_t width, uint32_t height, int repetitions) {
  // sessions[s * configs + c]
  std::vector<Session> sessions(loaded.size() * kConfigs.size());
  for (size_t s = 0; s < loaded.size(); ++s)
    for (size_t c = 0; c < kConfigs.size(); ++c) {
      auto& session = sessions[s * kConfigs.size() + c];
      session.scene = loaded[s].scene;
      auto made = plugins::makeDecoupledRenderer(
          device, session.scene, plugins::builtinRegistry(),
          kConfigs[c].decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward, {});
      session.decoupled = std::move(made.shading);
      session.renderer = std::move(made.renderer);
    }
  // With camera paths in the first scene, every scene is seen from there (what
  // a scene adds does not move the view); else each through its own default view.
  std::vector<scene::Camera> cameras;
  for (size_t s = 0; s < loaded.size(); ++s)
    cameras.push_back(loaded[0].cameraPaths.empty()
                          ? sessions[s * kConfigs.size()].renderer->camera({.width = width, .height = height})
                          : baselineCamera(loaded[0], *sessions[0].renderer, width, height));
  std::fprintf(stderr, "[bench] scene ratios %ux%u: %zu sessions, %d rounds\n", width, height, sessions.size(),
               repetitions);
  for (int rep = -1; rep < repetitions; ++rep)
    for (size_t i = 0; i < sessions.size(); ++i) {
      auto& session = sessions[i];
      const auto frame = session.renderer->render({.width = width, .height = height,
                                                   .cameraOverride = cameras[i / kConfigs.size()],
                                                   .occlusionCulling = !kConfigs[i % kConfigs.size()].asBefore});
      if (rep < 0) continue;  // warm-up: pipelines, the adjuster, last frame's visibility
      session.frameMs.push_back(frame.timings.gpuMs);
      for (const auto& p : frame.timings.passes) session.passMs[p.name].push_back(p.gpuMs);
    }
  nlohmann::json results = nlohmann::json::array();
  for (size_t s = 0; s < loaded.size(); ++s)
    for (size_t c = 0; c < kConfigs.size(); ++c) {
      const auto& session = sessions[s * kConfigs.size() + c];
      const double ms = median(session.frameMs);
      const double baseline = median(sessions[c].frameMs);
      // This scene and path as before issue 14 (configs 2, 3: the same paths as 0, 1).
      const double before = median(sessions[s * kConfigs.size() + c % 2 + 2].frameMs);
      const auto stats = session.decoupled->stats();
      results.push_back({{"scene", names[s]},
                         {"config", kConfigs[c].name},
                         {"decoupled", kConfigs[c].decoupled},
                         {"as_before", kConfigs[c].asBefore},
                         {"objects", session.scene.instances.size()},
                         {"frame_ms_median", ms},
                         {"frame_ms_samples", session.frameMs},
                         {"ratio_to_first", baseline > 0.0 ? ms / baseline : 0.0},
                         {"ratio_to_before", before > 0.0 ? ms / before : 0.0},
                         {"pass_ms_median", medians(session.passMs)},
                         {"composite_misses", stats.counters.compositeMisses}});
    }
  return {{"width", width}, {"height", height}, {"repetitions", repetitions}, {"configs", results}};
}

}  // namespace

void runSceneRatioBench(gpu::Context& context, gpu::Device& device, const SceneRatioArgs& args,
                        const std::filesystem::path& out) {
  if (args.scenes.size() < 2)
    throw std::invalid_argument("--scene-ratios: expected at least two scenes (the first is the baseline)");
  std::vector<LoadedScene> loaded;
  std::vector<std::string> names;
  for (const auto& path : args.scenes) {
    loaded.push_back(loadSceneArgument(path));
    names.push_back(std::filesystem::path(path).stem().string());
  }
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& size : args.sizes) {
    uint32_t w = 0, h = 0;
    parseSize("--sizes", size, w, h);
    runs.push_back(benchSize(device, loaded, names, w, h, args.repetitions));
  }
  writeTextFile(out / "scene-ratios.json", "results",
                nlohmann::json{{"machine", machineJson(context)}, {"runs", runs}}.dump(2) + "\n");
  std::printf("%-18s %-9s %-20s %9s %9s %10s %s\n", "scene", "size", "config", "frame ms", "÷ first", "÷ before",
              "passes (ms)");
  for (const auto& run : runs)
    for (const auto& c : run["configs"]) {
      std::string passes;
      for (const auto& [name, ms] : c["pass_ms_median"].items()) {
        char item[96];
        std::snprintf(item, sizeof item, "%s%s %.1f", passes.empty() ? "" : ", ", name.c_str(), ms.get<double>());
        passes += item;
      }
      std::printf("%-18s %4dx%-4d %-20s %9.2f %8.3f %9.3f %s\n", c["scene"].get<std::string>().c_str(),
                  run["width"].get<int>(), run["height"].get<int>(), c["config"].get<std::string>().c_str(),
                  c["frame_ms_median"].get<double>(), c["ratio_to_first"].get<double>(),
                  c["ratio_to_before"].get<double>(), passes.c_str());
    }
  std::printf("wrote %s/scene-ratios.json\n", out.c_str());
}

}  // namespace sg::app
