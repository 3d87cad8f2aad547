#include "bench_scenes.hpp"

#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <shadelgraph/render/renderer.hpp>

#include "bench_materials.hpp"
#include "bench_sessions.hpp"
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

// The first scene's camera: its first camera path at time 0 when it has one
// (framed for that scene's bounds), else the renderer's default view.
scene::Camera baselineCamera(const LoadedScene& loaded, const render::Renderer& renderer, uint32_t width,
                             uint32_t height) {
  if (loaded.cameraPaths.empty()) return renderer.camera({.width = width, .height = height});
  const auto pose = scene::evaluatePose(loaded.cameraPaths.front(), 0.0f);
  return scene::poseCamera(pose, scene::worldBounds(loaded.scene));
}

}  // namespace

nlohmann::json measureSceneRatios(gpu::Device& device, const std::vector<LoadedScene>& loaded,
                                  const std::vector<std::string>& names, uint32_t width, uint32_t height,
                                  int repetitions, bool withBefore, bool withoutOccludedSkip) {
  // configs[0, 1]: forward and decoupled now; [2, 3]: the same as before issue 14.
  const size_t configs = withBefore ? kConfigs.size() : 2;
  // sessions[s * configs + c]
  std::vector<BenchSession> sessions(loaded.size() * configs);
  for (size_t s = 0; s < loaded.size(); ++s)
    for (size_t c = 0; c < configs; ++c)
      sessions[s * configs + c].make(device, loaded[s].scene,
                                     kConfigs[c].decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward);
  // With camera paths in the first scene, every scene is seen from there (what
  // a scene adds does not move the view); else each through its own default view.
  std::vector<BenchSession*> timed;
  for (size_t i = 0; i < sessions.size(); ++i) {
    const size_t s = i / configs;
    sessions[i].view = {.width = width, .height = height,
                        .cameraOverride = loaded[0].cameraPaths.empty()
                                              ? sessions[s * configs].renderer->camera({.width = width, .height = height})
                                              : baselineCamera(loaded[0], *sessions[0].renderer, width, height),
                        .occlusionCulling = !kConfigs[i % configs].asBefore,
                        // Before issue 14 every frame had the depth pre-pass.
                        .zPrepass = kConfigs[i % configs].asBefore ? render::ZPrepass::On : render::ZPrepass::Auto};
    timed.push_back(&sessions[i]);
  }
  // Decoupled without the occluded-entry skip (DecoupledSettings::skipOccludedEntries), per scene, same view.
  std::vector<BenchSession> noSkip(withoutOccludedSkip ? loaded.size() : 0);
  for (size_t s = 0; s < noSkip.size(); ++s) {
    noSkip[s].make(device, loaded[s].scene, scene::ShadingMode::Decoupled, {.skipOccludedEntries = false});
    noSkip[s].view = sessions[s * configs + 1].view;
    timed.push_back(&noSkip[s]);
  }
  std::fprintf(stderr, "[bench] scene ratios %ux%u: %zu sessions, %d rounds\n", width, height, sessions.size(),
               repetitions);
  alternateFrames(timed, repetitions);
  nlohmann::json results = nlohmann::json::array();
  for (size_t s = 0; s < loaded.size(); ++s)
    for (size_t c = 0; c < configs; ++c) {
      const auto& session = sessions[s * configs + c];
      const double ms = session.frameMedian();
      const double baseline = sessions[c].frameMedian();
      // This scene and path as before issue 14 (configs 2, 3: the same paths as 0, 1).
      const double before = withBefore ? sessions[s * configs + c % 2 + 2].frameMedian() : 0.0;
      const auto stats = session.decoupled->stats();
      results.push_back({{"scene", names[s]},
                         {"config", kConfigs[c].name},
                         {"decoupled", kConfigs[c].decoupled},
                         {"as_before", kConfigs[c].asBefore},
                         {"objects", session.scene.instances.size()},
                         {"frame_ms_median", ms},
                         {"frame_ms_samples", session.frameMs},
                         {"ratio_to_first", baseline > 0.0 ? ms / baseline : 0.0},
                         {"ratio_to_before", withBefore ? nlohmann::json(before > 0.0 ? ms / before : 0.0) : nlohmann::json(nullptr)},
                         {"pass_ms_median", session.passMedians()},
                         {"visited_entries", stats.visitedEntries},
                         {"composite_misses", stats.counters.compositeMisses}});
    }
  for (size_t s = 0; s < noSkip.size(); ++s) {
    const double ms = noSkip[s].frameMedian();
    const auto stats = noSkip[s].decoupled->stats();
    results.push_back({{"scene", names[s]},
                       {"config", "decoupled no skip"},
                       {"decoupled", true},
                       {"as_before", false},
                       {"objects", noSkip[s].scene.instances.size()},
                       {"frame_ms_median", ms},
                       {"frame_ms_samples", noSkip[s].frameMs},
                       {"ratio_to_first", noSkip[0].frameMedian() > 0.0 ? ms / noSkip[0].frameMedian() : 0.0},
                       {"ratio_to_before", 0.0},
                       // The same scene's decoupled frame with the skip ÷ this one.
                       {"skip_ratio", ms > 0.0 ? sessions[s * configs + 1].frameMedian() / ms : 0.0},
                       {"visited_entries", stats.visitedEntries},
                       {"pass_ms_median", noSkip[s].passMedians()},
                       {"composite_misses", stats.counters.compositeMisses}});
  }
  return {{"width", width}, {"height", height}, {"repetitions", repetitions}, {"configs", results}};
}

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
    runs.push_back(measureSceneRatios(device, loaded, names, w, h, args.repetitions, true, args.withoutOccludedSkip));
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
