#include "bench_playback.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "animation_player.hpp"
#include "bench_materials.hpp"
#include "bench_sessions.hpp"
#include "output_file.hpp"
#include "scene_source.hpp"

namespace sg::app {
namespace {

constexpr float kFps = 30.0f;

struct Path {
  const char* name = "";
  bool decoupled = false;
  BenchSession session;  // its scene is posed by the path's own player: the renderer's objects follow it
  std::unique_ptr<AnimationPlayer> player;
  std::vector<double> shadelsPerPixel;
  uint64_t misses = 0, missesMax = 0;
};

nlohmann::json benchPlayback(gpu::Device& device, const std::string& scenePath, uint32_t width, uint32_t height,
                             int frames) {
  const scene::Scene loaded = loadSceneArgument(scenePath).scene;
  const std::string name = scenePath.empty() ? "default" : std::filesystem::path(scenePath).stem().string();
  if (loaded.animations.empty()) throw std::invalid_argument("--play: " + name + " has no animations");
  std::array<Path, 2> paths;
  paths[0].name = "forward";
  paths[1].name = "decoupled";
  paths[1].decoupled = true;
  for (auto& path : paths) {
    path.session.make(device, loaded, path.decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward);
    path.player = std::make_unique<AnimationPlayer>(path.session.scene, "all");
  }
  // As render frames it: the scene's first camera, else once around all the playback.
  const scene::Camera camera =
      loaded.cameras.empty()
          ? scene::frameBounds(paths[0].player->playbackBounds(), float(width) / float(height))
          : paths[0].session.renderer->camera({.width = width, .height = height});
  std::fprintf(stderr, "[bench] %s %ux%u: playing %d frames at %.0f fps, forward and decoupled alternated\n",
               name.c_str(), width, height, frames, double(kFps));
  for (int f = -1; f < frames; ++f)
    for (auto& path : paths) {
      path.player->poseAt(float(std::max(f, 0)) / kFps, *path.session.renderer);
      const auto frame = path.session.renderer->render({.width = width, .height = height, .cameraOverride = camera});
      if (f < 0) continue;  // warm-up: pipelines, the adjuster, the first pose's maps
      path.session.frameMs.push_back(frame.timings.gpuMs);
      if (!path.decoupled) continue;
      const auto counters = path.session.decoupled->stats().counters;
      path.shadelsPerPixel.push_back(plugins::shadelsPerCoveredPixel(counters));
      path.misses += counters.compositeMisses;
      path.missesMax = std::max<uint64_t>(path.missesMax, counters.compositeMisses);
    }
  const double forward = paths[0].session.frameMedian();
  nlohmann::json configs = nlohmann::json::array();
  for (const auto& path : paths) {
    const double ms = path.session.frameMedian();
    configs.push_back({{"config", path.name},
                       {"frame_ms_median", ms},
                       {"frame_ms_samples", path.session.frameMs},
                       {"ratio_to_forward", forward > 0.0 ? ms / forward : 0.0},
                       {"objects_decoupled", path.session.decoupled->stats().objects},
                       {"shadels_per_pixel_median", median(path.shadelsPerPixel)},
                       {"composite_misses", path.misses},
                       {"composite_misses_max", path.missesMax}});
  }
  return {{"scene", name}, {"width", width}, {"height", height}, {"frames", frames}, {"fps", kFps}, {"configs", configs}};
}

}  // namespace

void runPlaybackBench(gpu::Context& context, gpu::Device& device, const PlaybackBenchArgs& args,
                      const std::filesystem::path& out) {
  const nlohmann::json runs = runPerSceneAndSize(args.scenes, args.sizes, [&](const std::string& scene, uint32_t w, uint32_t h) {
    return benchPlayback(device, scene, w, h, args.frames);
  });
  writeTextFile(out / "playback.json", "results",
                nlohmann::json{{"machine", machineJson(context)}, {"runs", runs}}.dump(2) + "\n");
  std::printf("%-12s %-9s %-10s %9s %10s %8s %16s\n", "scene", "size", "config", "frame ms", "÷ forward", "shd/px",
              "misses (max/frame)");
  for (const auto& run : runs)
    for (const auto& c : run["configs"])
      std::printf("%-12s %4dx%-4d %-10s %9.2f %10.3f %8.2f %9llu (%llu)\n", run["scene"].get<std::string>().c_str(),
                  run["width"].get<int>(), run["height"].get<int>(), c["config"].get<std::string>().c_str(),
                  c["frame_ms_median"].get<double>(), c["ratio_to_forward"].get<double>(),
                  c["shadels_per_pixel_median"].get<double>(), (unsigned long long)c["composite_misses"].get<uint64_t>(),
                  (unsigned long long)c["composite_misses_max"].get<uint64_t>());
  std::printf("wrote %s/playback.json\n", out.c_str());
}

}  // namespace sg::app
