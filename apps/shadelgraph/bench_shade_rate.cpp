#include "bench_shade_rate.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <builtin_plugins.hpp>
#include <decoupled/decoupled_package.hpp>
#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/render/renderer.hpp>

#include "bench_materials.hpp"
#include "output_file.hpp"
#include "scene_source.hpp"

namespace sg::app {
namespace {

// The path: an orbit around the scene's centre, this many degrees a raster
// frame (15°/s at 30 frames a second: a slow pan that still uncovers and
// re-levels chunks every frame).
constexpr float kDegreesPerFrame = 0.5f;
// Frames rendered at the path's start before timing: pipelines, adjuster.
constexpr int kWarmupFrames = 3;

scene::Camera orbitCamera(scene::Camera camera, const scene::Scene& s, int frame) {
  const glm::vec3 center = scene::worldBounds(s).center();
  const glm::mat4 turn = glm::translate(glm::mat4(1.0f), center) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(kDegreesPerFrame * float(frame)), {0, 1, 0}) *
                         glm::translate(glm::mat4(1.0f), -center);
  camera.world = turn * camera.world;
  return camera;
}

// The moving object's offset at `frame`: a circle of this radius (in the
// scene's units) once every kObjectPeriod frames, in the horizontal plane.
constexpr float kObjectRadius = 0.25f;
constexpr int kObjectPeriod = 96;

glm::mat4 movedWorld(const glm::mat4& world, int frame) {
  const float angle = glm::two_pi<float>() * float(frame) / float(kObjectPeriod);
  const glm::vec3 offset(kObjectRadius * (std::cos(angle) - 1.0f), 0.0f, kObjectRadius * std::sin(angle));
  return glm::translate(glm::mat4(1.0f), offset) * world;
}

struct RateConfig {
  std::string name;
  bool decoupled = false;
  uint32_t rate = 1;
  std::optional<double> budgetMs;
  bool keepLayers = true;
};

struct RateSession {
  scene::Scene scene;
  std::shared_ptr<plugins::DecoupledShading> decoupled;
  std::unique_ptr<render::Renderer> renderer;
  std::vector<double> gpuMs, shadeFrameMs, fillFrameMs, psnrVsRate1;  // psnr: fill frames only
  std::map<std::string, std::vector<double>> shadePassMs, fillPassMs;  // forward's frames count as shade frames
  std::vector<bool> fillFrames;
  uint32_t maxMisses = 0, maxStaleAge = 0;
  uint64_t chunksShaded = 0, chunksReused = 0, chunksRefreshed = 0;
};

nlohmann::json runScene(gpu::Device& device, const ShadeRateBenchArgs& args, const std::string& scenePath,
                        uint32_t width, uint32_t height) {
  const auto loaded = loadSceneArgument(scenePath);
  const std::string sceneName = scenePath.empty() ? "default" : std::filesystem::path(scenePath).stem().string();
  std::vector<RateConfig> configs{{"forward", false, 1}};
  for (const int rate : args.rates) {
    configs.push_back({"decoupled rate " + std::to_string(rate), true, uint32_t(rate)});
    if (args.unkeptLayers)
      configs.push_back({"decoupled rate " + std::to_string(rate) + " unkept", true, uint32_t(rate), {}, false});
  }
  for (const double ms : args.budgets) {
    char name[64];
    std::snprintf(name, sizeof name, "decoupled budget %g ms", ms);
    configs.push_back({name, true, 1, ms});
  }
  std::vector<RateSession> sessions(configs.size());
  int rate1 = -1;
  for (size_t c = 0; c < configs.size(); ++c) {
    auto& s = sessions[c];
    s.scene = loaded.scene;
    if (!args.material.empty())
      for (auto& instance : s.scene.instances) instance.material = args.material;
    const auto mode = configs[c].decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward;
    auto made = plugins::makeDecoupledRenderer(device, s.scene, plugins::builtinRegistry(), mode,
                                               plugins::DecoupledSettings{.shadeRate = configs[c].rate,
                                                                          .shadeBudgetMs = configs[c].budgetMs,
                                                                          .keepViewIndependentLayers =
                                                                              configs[c].keepLayers});
    s.decoupled = std::move(made.shading);
    s.renderer = std::move(made.renderer);
    if (configs[c].decoupled && configs[c].rate == 1 && !configs[c].budgetMs && configs[c].keepLayers) rate1 = int(c);
  }
  std::optional<uint32_t> moving;
  if (!args.movingObject.empty()) {
    for (uint32_t i = 0; i < loaded.scene.instances.size(); ++i)
      if (loaded.scene.instances[i].name == args.movingObject) moving = i;
    if (!moving) throw std::invalid_argument("--move-object '" + args.movingObject + "': no such object in " + sceneName);
  }
  const scene::Camera start = sessions[0].renderer->camera({.width = width, .height = height});
  for (int f = -kWarmupFrames; f < args.pathFrames; ++f) {
    const scene::Camera camera = orbitCamera(start, loaded.scene, std::max(f, 0));
    std::vector<gpu::HostImage> images(configs.size());
    for (size_t c = 0; c < configs.size(); ++c) {
      auto& s = sessions[c];
      if (moving) s.renderer->setObjectTransform(*moving, movedWorld(loaded.scene.instances[*moving].world, std::max(f, 0)));
      // The scene's moving objects (the default scene's gold sphere) move 1/30 s a frame.
      auto frame = s.renderer->render(
          {.width = width, .height = height, .cameraOverride = camera, .time = float(std::max(f, 0)) / 30.0f});
      s.decoupled->observeTimings(frame.timings);
      if (f < 0) continue;
      const auto stats = s.decoupled->stats();
      s.gpuMs.push_back(frame.timings.gpuMs);
      const bool fill = configs[c].decoupled && !stats.shadeFrame;
      (fill ? s.fillFrameMs : s.shadeFrameMs).push_back(frame.timings.gpuMs);
      s.fillFrames.push_back(fill);
      for (const auto& p : frame.timings.passes) (fill ? s.fillPassMs : s.shadePassMs)[p.name].push_back(p.gpuMs);
      s.maxMisses = std::max(s.maxMisses, stats.counters.compositeMisses);
      s.chunksShaded += stats.counters.chunksShaded;
      s.chunksReused += stats.counters.chunksReused;
      s.chunksRefreshed += stats.counters.chunksRefreshed;
      s.maxStaleAge = std::max(s.maxStaleAge, stats.counters.staleMaxAge);
      images[c] = std::move(frame.image);
    }
    if (f < 0 || rate1 < 0) continue;
    for (size_t c = 0; c < configs.size(); ++c)
      if (configs[c].decoupled && int(c) != rate1 && sessions[c].fillFrames.back())
        sessions[c].psnrVsRate1.push_back(image::compareRgba8(images[size_t(rate1)].rgba8, images[c].rgba8).psnr);
  }
  std::fprintf(stderr, "[bench] %s %ux%u: %d path frames done\n", sceneName.c_str(), width, height, args.pathFrames);
  // Over a path, rate N alternates one shade frame with N - 1 fill frames: the
  // median of such a mix falls between the two and moves with the path's
  // length, so the mean (the amortized frame) is reported beside it.
  const auto mean = [](const std::vector<double>& v) {
    double sum = 0.0;
    for (const double x : v) sum += x;
    return v.empty() ? 0.0 : sum / double(v.size());
  };
  const double forwardMedian = median(sessions[0].gpuMs), forwardMean = mean(sessions[0].gpuMs);
  nlohmann::json results = nlohmann::json::array();
  for (size_t c = 0; c < configs.size(); ++c) {
    const auto& s = sessions[c];
    const double ms = median(s.gpuMs), msMean = mean(s.gpuMs);
    results.push_back({{"config", configs[c].name},
                       {"decoupled", configs[c].decoupled},
                       {"shade_rate", configs[c].rate},
                       {"frame_ms_median", ms},
                       {"frame_ms_mean", msMean},
                       {"ratio_to_forward", forwardMedian > 0 ? ms / forwardMedian : 0.0},
                       {"ratio_mean_to_forward", forwardMean > 0 ? msMean / forwardMean : 0.0},
                       {"shade_frame_ms_median", median(s.shadeFrameMs)},
                       {"fill_frame_ms_median", median(s.fillFrameMs)},
                       {"frame_ms_samples", s.gpuMs},
                       {"shade_frame_pass_ms_median", medians(s.shadePassMs)},
                       {"fill_frame_pass_ms_median", medians(s.fillPassMs)},
                       {"composite_misses_max", s.maxMisses},
                       {"chunks_shaded_per_frame", double(s.chunksShaded) / double(args.pathFrames)},
                       {"chunks_reused_per_frame", double(s.chunksReused) / double(args.pathFrames)},
                       {"chunks_refreshed_per_frame", double(s.chunksRefreshed) / double(args.pathFrames)},
                       {"stale_max_age_max", s.maxStaleAge},
                       {"budget_ms", configs[c].budgetMs ? nlohmann::json(*configs[c].budgetMs) : nlohmann::json(nullptr)},
                       {"keep_view_independent_layers", configs[c].keepLayers},
                       {"psnr_vs_rate1_median", s.psnrVsRate1.empty() ? nlohmann::json(nullptr)
                                                                       : nlohmann::json(median(s.psnrVsRate1))}});
  }
  return {{"scene", sceneName}, {"width", width}, {"height", height}, {"path_frames", args.pathFrames},
          {"moving_object", args.movingObject}, {"material", args.material},
          {"degrees_per_frame", kDegreesPerFrame}, {"warmup_frames", kWarmupFrames}, {"configs", results}};
}

}  // namespace

void runShadeRateBench(gpu::Context& context, gpu::Device& device, const ShadeRateBenchArgs& args,
                       const std::filesystem::path& out) {
  const nlohmann::json runs = runPerSceneAndSize(args.scenes, args.sizes, [&](const std::string& scene, uint32_t w,
                                                                             uint32_t h) {
    return runScene(device, args, scene, w, h);
  });
  const nlohmann::json results{{"machine", machineJson(context)}, {"runs", runs}};
  writeTextFile(out / "shade-rate.json", "results", results.dump(2) + "\n");
  std::printf("%-14s %-9s %-26s %8s %6s %8s %6s %8s %8s %7s %7s %7s %6s %4s\n", "scene", "size", "config", "median",
              "÷fwd", "mean", "÷fwd", "shade ms", "fill ms", "shaded", "reused", "PSNR r1", "misses", "age");
  for (const auto& run : runs)
    for (const auto& c : run["configs"])
      std::printf("%-14s %4dx%-4d %-26s %8.2f %6.3f %8.2f %6.3f %8.2f %8.2f %7.0f %7.0f %7.2f %6u %4u\n",
                  run["scene"].get<std::string>().c_str(), run["width"].get<int>(), run["height"].get<int>(),
                  c["config"].get<std::string>().c_str(), c["frame_ms_median"].get<double>(),
                  c["ratio_to_forward"].get<double>(), c["frame_ms_mean"].get<double>(),
                  c["ratio_mean_to_forward"].get<double>(), c["shade_frame_ms_median"].get<double>(),
                  c["fill_frame_ms_median"].get<double>(), c["chunks_shaded_per_frame"].get<double>(),
                  c["chunks_reused_per_frame"].get<double>(),
                  c["psnr_vs_rate1_median"].is_null() ? 0.0 : c["psnr_vs_rate1_median"].get<double>(),
                  c["composite_misses_max"].get<uint32_t>(), c["stale_max_age_max"].get<uint32_t>());
  std::printf("wrote %s/shade-rate.json\n", out.c_str());
}

}  // namespace sg::app
