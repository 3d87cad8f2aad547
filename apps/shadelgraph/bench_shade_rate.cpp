#include "bench_shade_rate.hpp"

#include <algorithm>
#include <chrono>
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
#include "bench_path_quality.hpp"
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
  bool inFlight = false;  // two frames in flight: the shade frame is the raster frame's tail
};

// What a pass is for: the raster frame's own work (what forward also pays, and
// mark and composite), the shade space's bookkeeping, or shading itself.
enum class PassGroup { Raster, ShadeSpace, Shading };

PassGroup groupOf(const std::string& pass) {
  if (pass.rfind("layer-shade", 0) == 0 || pass.rfind("shade-frame", 0) == 0 || pass == "shade-reuse")
    return PassGroup::Shading;
  for (const char* bookkeeping : {"shadel-clear", "shadel-mask-clear", "shadel-mark-neighbours", "shadel-allocate",
                                  "work-aggregate", "shadel-gutter", "counters-readback", "support-expand"})
    if (pass == bookkeeping) return PassGroup::ShadeSpace;
  return PassGroup::Raster;
}

// One raster frame's GPU span split into the groups, and the span's time outside every pass (gaps).
struct FrameGroups {
  double raster = 0.0, shadeSpace = 0.0, shading = 0.0, gaps = 0.0;
};

FrameGroups groupsOf(const gpu::FrameTimings& timings) {
  FrameGroups g;
  double passes = 0.0;
  for (const auto& p : timings.passes) {
    if (p.tail) continue;
    passes += p.gpuMs;
    const PassGroup group = groupOf(p.name);
    (group == PassGroup::Raster ? g.raster : group == PassGroup::ShadeSpace ? g.shadeSpace : g.shading) += p.gpuMs;
  }
  g.gaps = std::max(0.0, timings.gpuMs - passes);
  return g;
}

double mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  return v.empty() ? 0.0 : sum / double(v.size());
}

struct RateSession {
  scene::Scene scene;
  std::shared_ptr<plugins::DecoupledShading> decoupled;
  std::unique_ptr<render::Renderer> renderer;
  std::vector<double> gpuMs, tailMs, shadeFrameMs, fillFrameMs, psnrVsRate1;  // psnr: fill frames only
  std::map<std::string, std::vector<double>> shadePassMs, fillPassMs, tailPassMs;  // forward's frames count as shade frames
  std::vector<FrameGroups> groups;
  std::vector<bool> fillFrames;
  PathQuality quality;
  std::vector<double> blockMsPerFrame;  // wall time a frame over consecutive frames (blocks)
  uint32_t maxMisses = 0, maxStaleAge = 0;
  uint64_t chunksShaded = 0, chunksReused = 0, chunksRefreshed = 0;

  // The tails (shade frames in flight) completed since the last call, counted to the last path frame.
  void collectTails(bool count) {
    for (const auto& tail : renderer->finishFrames()) {
      if (!count || tailMs.empty()) continue;
      for (const auto& p : tail.passes) {  // the tail's passes (its FrameTimings has no span of its own)
        tailMs.back() += p.gpuMs;
        tailPassMs[p.name].push_back(p.gpuMs);
      }
    }
  }
};

nlohmann::json groupMedians(const std::vector<FrameGroups>& groups, const std::vector<bool>& fill,
                            std::optional<bool> onlyFill) {
  std::vector<double> raster, shadeSpace, shading, gaps;
  for (size_t i = 0; i < groups.size(); ++i) {
    if (onlyFill && fill[i] != *onlyFill) continue;
    raster.push_back(groups[i].raster);
    shadeSpace.push_back(groups[i].shadeSpace);
    shading.push_back(groups[i].shading);
    gaps.push_back(groups[i].gaps);
  }
  if (raster.empty()) return nullptr;
  return {{"raster", median(raster)}, {"shade_space", median(shadeSpace)}, {"shading", median(shading)},
          {"gaps", median(gaps)}};
}

// Consecutive frames of one configuration, wall time: what frames in flight buy
// (the tail of frame N runs while N + 1 is recorded), not visible in GPU spans.
constexpr int kBlockFrames = 8;
constexpr int kBlockRounds = 3;

nlohmann::json runScene(gpu::Device& device, const ShadeRateBenchArgs& args, const std::string& scenePath,
                        uint32_t width, uint32_t height) {
  const auto loaded = loadSceneArgument(scenePath);
  const std::string sceneName = scenePath.empty() ? "default" : std::filesystem::path(scenePath).stem().string();
  std::vector<RateConfig> configs{{"forward", false, 1}};
  for (const int rate : args.rates) {
    configs.push_back({"decoupled rate " + std::to_string(rate), true, uint32_t(rate)});
    if (args.unkeptLayers)
      configs.push_back({"decoupled rate " + std::to_string(rate) + " unkept", true, uint32_t(rate), {}, false});
    if (args.framesInFlight > 1 && rate > 1)
      configs.push_back({"decoupled rate " + std::to_string(rate) + " in flight", true, uint32_t(rate), {}, true, true});
  }
  for (const double ms : args.budgets) {
    char name[64];
    std::snprintf(name, sizeof name, "decoupled budget %g ms", ms);
    configs.push_back({name, true, 1, ms});
  }
  const auto makeScene = [&] {
    scene::Scene s = loaded.scene;
    if (!args.material.empty())
      for (auto& instance : s.instances) instance.material = args.material;
    return s;
  };
  std::vector<RateSession> sessions(configs.size());
  int rate1 = -1;
  for (size_t c = 0; c < configs.size(); ++c) {
    auto& s = sessions[c];
    s.scene = makeScene();
    const auto mode = configs[c].decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward;
    auto made = plugins::makeDecoupledRenderer(device, s.scene, plugins::builtinRegistry(), mode,
                                               plugins::DecoupledSettings{.shadeRate = configs[c].rate,
                                                                          .overlap = configs[c].inFlight,
                                                                          .shadeBudgetMs = configs[c].budgetMs,
                                                                          .keepViewIndependentLayers =
                                                                              configs[c].keepLayers});
    s.decoupled = std::move(made.shading);
    s.renderer = std::move(made.renderer);
    if (configs[c].decoupled && configs[c].rate == 1 && !configs[c].budgetMs && configs[c].keepLayers) rate1 = int(c);
  }
  // The reference: forward, its own session (its frames at referenceScale² the
  // pixels would disturb forward's timed ones), at the same pose and time.
  RateSession reference;
  reference.scene = makeScene();
  auto madeReference = plugins::makeDecoupledRenderer(device, reference.scene, plugins::builtinRegistry(),
                                                      scene::ShadingMode::Forward, {});
  reference.decoupled = std::move(madeReference.shading);
  reference.renderer = std::move(madeReference.renderer);
  std::optional<uint32_t> moving;
  if (!args.movingObject.empty()) {
    for (uint32_t i = 0; i < loaded.scene.instances.size(); ++i)
      if (loaded.scene.instances[i].name == args.movingObject) moving = i;
    if (!moving) throw std::invalid_argument("--move-object '" + args.movingObject + "': no such object in " + sceneName);
  }
  const scene::Camera start = sessions[0].renderer->camera({.width = width, .height = height});
  const uint32_t scale = uint32_t(args.referenceScale);
  // Frame `f` of configuration (or the reference) `s`: the orbit's pose, the objects' motion.
  const auto renderAt = [&](RateSession& s, int f, uint32_t framesInFlight, bool readback, uint32_t sizeScale) {
    if (moving) s.renderer->setObjectTransform(*moving, movedWorld(loaded.scene.instances[*moving].world, f));
    // The scene's moving objects (the default scene's gold sphere) move 1/30 s a frame.
    return s.renderer->render({.width = width * sizeScale, .height = height * sizeScale,
                               .cameraOverride = orbitCamera(start, loaded.scene, f), .time = float(f) / 30.0f,
                               .framesInFlight = framesInFlight, .readback = readback});
  };
  for (int f = -kWarmupFrames; f < args.pathFrames; ++f) {
    const int pose = std::max(f, 0);
    std::optional<image::Rgba8Image> referenceImage;
    if (f >= 0) referenceImage = downsample(renderAt(reference, pose, 1, true, scale).image, scale);
    std::vector<gpu::HostImage> images(configs.size());
    for (size_t c = 0; c < configs.size(); ++c) {
      auto& s = sessions[c];
      if (configs[c].inFlight) s.collectTails(f > 0);  // the last frame's shade frame: done on one queue by now
      auto frame = renderAt(s, pose, configs[c].inFlight ? 2 : 1, true, 1);
      s.decoupled->observeTimings(frame.timings);
      if (f < 0) continue;
      const auto stats = s.decoupled->stats();
      s.gpuMs.push_back(frame.timings.gpuMs);
      s.tailMs.push_back(0.0);
      const bool fill = configs[c].decoupled && !stats.shadeFrame;
      (fill ? s.fillFrameMs : s.shadeFrameMs).push_back(frame.timings.gpuMs);
      s.fillFrames.push_back(fill);
      for (const auto& p : frame.timings.passes)
        if (!p.tail) (fill ? s.fillPassMs : s.shadePassMs)[p.name].push_back(p.gpuMs);
      s.groups.push_back(groupsOf(frame.timings));
      s.maxMisses = std::max(s.maxMisses, stats.counters.compositeMisses);
      s.chunksShaded += stats.counters.chunksShaded;
      s.chunksReused += stats.counters.chunksReused;
      s.chunksRefreshed += stats.counters.chunksRefreshed;
      s.maxStaleAge = std::max(s.maxStaleAge, stats.counters.staleMaxAge);
      s.quality.add(toImage(frame.image), *referenceImage, fill);
      images[c] = std::move(frame.image);
    }
    if (f < 0 || rate1 < 0) continue;
    for (size_t c = 0; c < configs.size(); ++c)
      if (configs[c].decoupled && int(c) != rate1 && sessions[c].fillFrames.back())
        sessions[c].psnrVsRate1.push_back(image::compareRgba8(images[size_t(rate1)].rgba8, images[c].rgba8).psnr);
  }
  for (size_t c = 0; c < configs.size(); ++c)
    if (configs[c].inFlight) sessions[c].collectTails(true);
  std::fprintf(stderr, "[bench] %s %ux%u: %d path frames done\n", sceneName.c_str(), width, height, args.pathFrames);

  // With frames in flight: blocks of consecutive frames (no readback: a frame
  // loop presents, it does not read back), forward and every rate with and
  // without, alternated block by block; each block ends when its last tail has.
  if (args.framesInFlight > 1) {
    std::vector<size_t> blockConfigs{0};
    for (size_t c = 1; c < configs.size(); ++c)
      if (configs[c].inFlight || (!configs[c].budgetMs && configs[c].keepLayers && configs[c].rate > 1))
        blockConfigs.push_back(c);
    for (int round = 0; round < kBlockRounds; ++round)
      for (const size_t c : blockConfigs) {
        auto& s = sessions[c];
        const auto begin = std::chrono::steady_clock::now();
        for (int k = 0; k < kBlockFrames; ++k) {
          const auto frame = renderAt(s, args.pathFrames + round * kBlockFrames + k, configs[c].inFlight ? 2 : 1,
                                      false, 1);
          s.decoupled->observeTimings(frame.timings);
          s.maxMisses = std::max(s.maxMisses, s.decoupled->stats().counters.compositeMisses);
        }
        s.renderer->finishFrames();
        s.blockMsPerFrame.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count() / kBlockFrames);
      }
    std::fprintf(stderr, "[bench] %s %ux%u: %d rounds of %d consecutive frames done\n", sceneName.c_str(), width,
                 height, kBlockRounds, kBlockFrames);
  }

  // Over a path, rate N alternates one shade frame with N - 1 fill frames: the
  // median of such a mix falls between the two and moves with the path's
  // length, so the mean (the amortized frame) is reported beside it.
  const double forwardMedian = median(sessions[0].gpuMs), forwardMean = mean(sessions[0].gpuMs);
  const double forwardBlock = median(sessions[0].blockMsPerFrame);
  nlohmann::json results = nlohmann::json::array();
  for (size_t c = 0; c < configs.size(); ++c) {
    const auto& s = sessions[c];
    const double ms = median(s.gpuMs), msMean = mean(s.gpuMs);
    // On one queue a shade frame in flight still runs before the next raster
    // frame: the raster frame plus its tail is what the device spends.
    std::vector<double> withTail(s.gpuMs.size()), tails;
    for (size_t i = 0; i < s.gpuMs.size(); ++i) {
      withTail[i] = s.gpuMs[i] + s.tailMs[i];
      if (s.tailMs[i] > 0.0) tails.push_back(s.tailMs[i]);
    }
    std::vector<double> raster;
    for (const auto& g : s.groups) raster.push_back(g.raster);
    nlohmann::json result{{"config", configs[c].name},
                          {"decoupled", configs[c].decoupled},
                          {"shade_rate", configs[c].rate},
                          {"in_flight", configs[c].inFlight},
                          {"frame_ms_median", ms},
                          {"frame_ms_mean", msMean},
                          {"ratio_to_forward", forwardMedian > 0 ? ms / forwardMedian : 0.0},
                          {"ratio_mean_to_forward", forwardMean > 0 ? msMean / forwardMean : 0.0},
                          {"shade_frame_ms_median", median(s.shadeFrameMs)},
                          {"fill_frame_ms_median", median(s.fillFrameMs)},
                          {"frame_ms_samples", s.gpuMs},
                          {"tail_ms_median", tails.empty() ? nlohmann::json(nullptr) : nlohmann::json(median(tails))},
                          {"frame_with_tail_ms_median", median(withTail)},
                          {"frame_with_tail_ms_mean", mean(withTail)},
                          {"ratio_mean_with_tail_to_forward", forwardMean > 0 ? mean(withTail) / forwardMean : 0.0},
                          {"tail_pass_ms_median", medians(s.tailPassMs)},
                          {"shade_frame_pass_ms_median", medians(s.shadePassMs)},
                          {"fill_frame_pass_ms_median", medians(s.fillPassMs)},
                          {"pass_groups_ms_median", groupMedians(s.groups, s.fillFrames, {})},
                          {"shade_frame_pass_groups_ms_median", groupMedians(s.groups, s.fillFrames, false)},
                          {"fill_frame_pass_groups_ms_median", groupMedians(s.groups, s.fillFrames, true)},
                          {"raster_passes_ms_median", median(raster)},
                          {"raster_passes_ratio_to_forward", forwardMedian > 0 ? median(raster) / forwardMedian : 0.0},
                          {"composite_misses_max", s.maxMisses},
                          {"chunks_shaded_per_frame", double(s.chunksShaded) / double(args.pathFrames)},
                          {"chunks_reused_per_frame", double(s.chunksReused) / double(args.pathFrames)},
                          {"chunks_refreshed_per_frame", double(s.chunksRefreshed) / double(args.pathFrames)},
                          {"stale_max_age_max", s.maxStaleAge},
                          {"budget_ms", configs[c].budgetMs ? nlohmann::json(*configs[c].budgetMs) : nlohmann::json(nullptr)},
                          {"keep_view_independent_layers", configs[c].keepLayers},
                          {"psnr_vs_rate1_median", s.psnrVsRate1.empty() ? nlohmann::json(nullptr)
                                                                          : nlohmann::json(median(s.psnrVsRate1))},
                          {"consecutive_wall_ms_per_frame",
                           s.blockMsPerFrame.empty() ? nlohmann::json(nullptr) : nlohmann::json(median(s.blockMsPerFrame))},
                          {"consecutive_wall_ratio_to_forward",
                           s.blockMsPerFrame.empty() || forwardBlock <= 0.0
                               ? nlohmann::json(nullptr)
                               : nlohmann::json(median(s.blockMsPerFrame) / forwardBlock)}};
    result.update(s.quality.json());
    results.push_back(std::move(result));
  }
  return {{"scene", sceneName}, {"width", width}, {"height", height}, {"path_frames", args.pathFrames},
          {"moving_object", args.movingObject}, {"material", args.material},
          {"degrees_per_frame", kDegreesPerFrame}, {"warmup_frames", kWarmupFrames},
          {"reference_spp", args.referenceScale * args.referenceScale}, {"frames_in_flight", args.framesInFlight},
          {"consecutive_block_frames", args.framesInFlight > 1 ? kBlockFrames : 0},
          {"consecutive_block_rounds", args.framesInFlight > 1 ? kBlockRounds : 0}, {"configs", results}};
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
  std::printf("%-14s %-9s %-28s %8s %6s %8s %6s %8s %8s %7s %6s %8s %7s %6s %4s\n", "scene", "size", "config",
              "median", "÷fwd", "mean", "÷fwd", "shade ms", "fill ms", "FLIP", "PSNR", "flicker+", "PSNR r1", "misses",
              "age");
  for (const auto& run : runs)
    for (const auto& c : run["configs"])
      std::printf("%-14s %4dx%-4d %-28s %8.2f %6.3f %8.2f %6.3f %8.2f %8.2f %7.4f %6.2f %8.5f %7.2f %6u %4u\n",
                  run["scene"].get<std::string>().c_str(), run["width"].get<int>(), run["height"].get<int>(),
                  c["config"].get<std::string>().c_str(), c["frame_ms_median"].get<double>(),
                  c["ratio_to_forward"].get<double>(), c["frame_ms_mean"].get<double>(),
                  c["ratio_mean_to_forward"].get<double>(), c["shade_frame_ms_median"].get<double>(),
                  c["fill_frame_ms_median"].get<double>(), c["flip_mean"].get<double>(), c["psnr_median"].get<double>(),
                  c["flicker_excess"].get<double>(),
                  c["psnr_vs_rate1_median"].is_null() ? 0.0 : c["psnr_vs_rate1_median"].get<double>(),
                  c["composite_misses_max"].get<uint32_t>(), c["stale_max_age_max"].get<uint32_t>());
  // Where the raster frame's time goes (medians over the path) and, with frames
  // in flight, the shade frame's tail and the wall time of consecutive frames.
  for (const auto& run : runs)
    for (const auto& c : run["configs"]) {
      const auto& g = c["pass_groups_ms_median"];
      std::printf("%s %dx%d %s: raster passes %.2f ms (%.3f× forward), shade space %.2f, shading %.2f, gaps %.2f",
                  run["scene"].get<std::string>().c_str(), run["width"].get<int>(), run["height"].get<int>(),
                  c["config"].get<std::string>().c_str(), g["raster"].get<double>(),
                  c["raster_passes_ratio_to_forward"].get<double>(), g["shade_space"].get<double>(),
                  g["shading"].get<double>(), g["gaps"].get<double>());
      if (!c["tail_ms_median"].is_null())
        std::printf("; tail %.2f ms, frame + tail mean %.2f ms (%.3f× forward)", c["tail_ms_median"].get<double>(),
                    c["frame_with_tail_ms_mean"].get<double>(), c["ratio_mean_with_tail_to_forward"].get<double>());
      if (!c["consecutive_wall_ms_per_frame"].is_null())
        std::printf("; consecutive frames %.2f ms wall (%.3f× forward)", c["consecutive_wall_ms_per_frame"].get<double>(),
                    c["consecutive_wall_ratio_to_forward"].get<double>());
      std::printf("\n");
    }
  std::printf("wrote %s/shade-rate.json\n", out.c_str());
}

}  // namespace sg::app
