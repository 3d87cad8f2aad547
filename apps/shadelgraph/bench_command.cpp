// shadelgraph bench [scene] --out DIR: what accuracy costs in time. Every
// configuration renders the same frames in one run, alternating, several
// repetitions; medians are reported with shading cost, memory, and error
// against a 16-sample forward reference (ꟻLIP, PSNR) and flicker along a
// camera path with sub-pixel motion. Writes results.json and results.csv.
// With --materials, the material sweep of bench_materials.cpp runs instead.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include <builtin_materials.hpp>
#include <builtin_shaders.hpp>
#include <builtin_plugins.hpp>
#include <decoupled/decoupled_package.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/image/flicker.hpp>
#include <shadelgraph/image/flip.hpp>
#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/render/renderer.hpp>

#include "bench_effects.hpp"
#include "bench_graph.hpp"
#include "bench_materials.hpp"
#include "bench_playback.hpp"
#include "bench_scenes.hpp"
#include "bench_sessions.hpp"
#include "bench_shade_rate.hpp"
#include "bench_targets.hpp"
#include "command_options.hpp"
#include "commands.hpp"
#include "option_checks.hpp"
#include "output_file.hpp"
#include "scene_source.hpp"

namespace sg::app {

image::Rgba8Image toImage(const gpu::HostImage& h) { return {h.width, h.height, h.rgba8}; }

image::Rgba8Image downsample(const gpu::HostImage& big, uint32_t scale) {
  // sRGB decode by table: the same values as the formula, without a pow per sample.
  static const std::array<double, 256> kLinear = [] {
    std::array<double, 256> table{};
    for (int v = 0; v < 256; ++v) {
      const double c = v / 255.0;
      table[size_t(v)] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    }
    return table;
  }();
  auto toLinear = [](uint8_t v) { return kLinear[v]; };
  auto toSrgb = [](double l) {
    const double c = l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
    return uint8_t(std::clamp(c * 255.0 + 0.5, 0.0, 255.0));
  };
  image::Rgba8Image out{big.width / scale, big.height / scale, {}};
  out.pixels.resize(size_t(out.width) * out.height * 4);
  for (uint32_t y = 0; y < out.height; ++y)
    for (uint32_t x = 0; x < out.width; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0;
        for (uint32_t j = 0; j < scale; ++j)
          for (uint32_t i = 0; i < scale; ++i) sum += toLinear(big.pixel(x * scale + i, y * scale + j)[c]);
        out.pixels[(size_t(y) * out.width + x) * 4 + c] = c == 3 ? 255 : toSrgb(sum / double(scale * scale));
      }
  return out;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

nlohmann::json medians(const std::map<std::string, std::vector<double>>& samples) {
  nlohmann::json result = nlohmann::json::object();
  for (const auto& [name, values] : samples) result[name] = median(values);
  return result;
}

namespace {

std::string cpuName() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

}  // namespace

nlohmann::json runPerSceneAndSize(
    const std::vector<std::string>& scenes, const std::vector<std::string>& sizes,
    const std::function<nlohmann::json(const std::string& scene, uint32_t width, uint32_t height)>& run) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& scene : scenes.empty() ? std::vector<std::string>{""} : scenes)
    for (const auto& size : sizes) {
      uint32_t w = 0, h = 0;
      parseSize("--sizes", size, w, h);
      runs.push_back(run(scene, w, h));
    }
  return runs;
}

nlohmann::json hostJson() { return {{"cpu", cpuName()}, {"cores", std::thread::hardware_concurrency()}}; }

nlohmann::json machineJson(const gpu::Context& context) {
  nlohmann::json machine = hostJson();
  machine["device"] = context.deviceName();
  machine["driver"] = context.driverDescription();
  return machine;
}

namespace {

struct Config {
  std::string name;
  bool decoupled = false;
  int filter = 2;
  std::optional<float> bias;  // decoupled: fixed bias; empty = adjuster
  bool baseline = false;      // decoupled: shadel-mark as before issue 14
};

std::vector<Config> sweep(const BenchArgs& args) {
  std::vector<Config> configs{{"forward", false}};
  for (int filter : {0, 1, 2}) {
    const std::string name = std::string("decoupled ") + (filter == 0 ? "point" : filter == 1 ? "bilinear" : "trilinear");
    configs.push_back({name, true, filter, 0.0f});
    if (args.baseline) configs.push_back({name + " (baseline)", true, filter, 0.0f, true});
  }
  if (args.filtersOnly) return configs;
  for (float bias : {-1.0f, -0.5f, 0.5f, 1.0f, 1.5f, 2.0f}) {
    char name[64];
    std::snprintf(name, sizeof name, "decoupled bias %+.1f", double(bias));
    configs.push_back({name, true, 2, bias});
  }
  return configs;
}

// The camera at step `i` of a sideways move by a quarter pixel per frame (at
// the distance of the scene's centre): sub-pixel motion, where shading
// aliasing shows as flicker.
scene::Camera pathCamera(scene::Camera camera, const scene::Scene& s, uint32_t height, int i) {
  const float distance = glm::distance(camera.position(), scene::worldBounds(s).center());
  const float pixel = 2.0f * distance * std::tan(camera.yfov * 0.5f) / float(height);
  camera.world[3] += camera.world[0] * (0.25f * pixel * float(i));
  return camera;
}

// The shimmer case: the default scene's rippled gold sphere filling most of
// the view, where a normal pattern finer than a pixel aliases under motion.
scene::Camera shimmerCamera() {
  scene::Camera camera{.name = "shimmer", .yfov = 0.6f, .znear = 0.05f, .zfar = 50.0f};
  camera.world = scene::lookAtWorld({0.6f, 1.6f, 2.4f}, {0.0f, 1.2f, -1.5f});  // the sphere sits at (0, 1.2, -1.5)
  return camera;
}

nlohmann::json benchScene(gpu::Device& device, const std::string& scenePath, uint32_t width, uint32_t height,
                          const BenchArgs& args, const std::filesystem::path& out,
                          std::optional<scene::Camera> cameraOverride = {}, std::string runName = {}) {
  const auto loaded = loadSceneArgument(scenePath);
  std::string sceneName = scenePath.empty() ? "default" : std::filesystem::path(scenePath).stem().string();
  if (!runName.empty()) sceneName = runName;
  const auto configs = sweep(args);
  std::vector<BenchSession> sessions(configs.size());
  for (size_t c = 0; c < configs.size(); ++c) {
    const auto mode = configs[c].decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward;
    // A fixed bias below zero asks for up to 4x more shadels per level: give
    // it the storage, so the sweep measures shading, not overflow.
    const double storage = 2.0 * std::pow(4.0, std::max(0.0, -double(configs[c].bias.value_or(0.0f)))) * 1.5;
    sessions[c].make(device, loaded.scene, mode,
                     plugins::DecoupledSettings{.storageFactor = storage, .filter = configs[c].filter,
                                                .baseline = configs[c].baseline, .fixedBias = configs[c].bias});
  }
  const scene::Camera camera =
      cameraOverride ? *cameraOverride : sessions[0].renderer->camera({.width = width, .height = height});

  // Reference: forward with referenceScale² samples per pixel, box-filtered.
  std::fprintf(stderr, "[bench] %s %ux%u: reference (%d spp)\n", sceneName.c_str(), width, height,
               args.referenceScale * args.referenceScale);
  const uint32_t scale = uint32_t(args.referenceScale);
  auto reference = [&](int step) {
    return downsample(sessions[0].renderer->render({.width = width * scale, .height = height * scale,
                                                    .cameraOverride = pathCamera(camera, loaded.scene, height * scale, step * int(scale))})
                          .image,
                      scale);
  };
  std::vector<image::Rgba8Image> referencePath;
  for (int i = 0; i < args.flickerFrames; ++i) referencePath.push_back(reference(i));
  image::writePng(out / (sceneName + "-" + std::to_string(width) + "-reference.png"), width, height,
                  referencePath[0].pixels.data());

  // Timing: configurations alternate inside each repetition, after a warm-up frame each.
  std::vector<BenchSession*> timed;
  for (auto& s : sessions) {
    s.view = {.width = width, .height = height, .cameraOverride = camera};
    timed.push_back(&s);
  }
  alternateFrames(timed, args.repetitions);

  nlohmann::json results = nlohmann::json::array();
  for (size_t c = 0; c < configs.size(); ++c) {
    std::fprintf(stderr, "[bench] %s %ux%u: %s\n", sceneName.c_str(), width, height, configs[c].name.c_str());
    const auto test = toImage(sessions[c].last.image);
    const auto flip = image::flipLdr(referencePath[0], test);
    const auto diff = image::compareRgba8(referencePath[0].pixels, test.pixels);
    std::vector<image::Rgba8Image> path;
    for (int i = 0; i < args.flickerFrames; ++i)
      path.push_back(toImage(sessions[c].renderer
                                 ->render({.width = width, .height = height,
                                           .cameraOverride = pathCamera(camera, loaded.scene, height, i)})
                                 .image));
    const auto flicker = image::flicker(path, referencePath);
    const auto stats = sessions[c].decoupled->stats();
    const nlohmann::json passes = sessions[c].passMedians();
    const std::string file = sceneName + "-" + std::to_string(width) + "-" + configs[c].name + ".png";
    image::writePng(out / file, test.width, test.height, test.pixels.data());
    image::writePng(out / ("flip-" + file), width, height, image::flipHeatmap(flip).pixels.data());
    results.push_back({{"config", configs[c].name},
                       {"decoupled", configs[c].decoupled},
                       {"filter", configs[c].filter},
                       {"bias", configs[c].bias ? nlohmann::json(*configs[c].bias) : nlohmann::json(nullptr)},
                       {"frame_ms_median", sessions[c].frameMedian()},
                       {"frame_ms_samples", sessions[c].frameMs},
                       {"pass_ms_median", passes},
                       {"shadels_per_pixel", plugins::shadelsPerCoveredPixel(stats.counters)},
                       {"shade_memory_bytes", configs[c].decoupled ? stats.storageBytes + stats.remapBytes + stats.idMapBytes : 0},
                       {"overflow_chunks", stats.counters.overflowChunks},
                       {"composite_misses", stats.counters.compositeMisses},
                       {"flip_mean", flip.mean},
                       {"psnr", diff.psnr},
                       {"flicker", flicker.test},
                       {"flicker_reference", flicker.reference},
                       {"flicker_excess", flicker.excess},
                       {"flicker_ratio", flicker.ratio},
                       {"image", file}});
  }
  return {{"scene", sceneName}, {"width", width}, {"height", height}, {"repetitions", args.repetitions},
          {"reference_spp", args.referenceScale * args.referenceScale}, {"flicker_frames", args.flickerFrames},
          {"configs", results}};
}

void writeCsv(const std::filesystem::path& file, const nlohmann::json& runs) {
  std::ostringstream csv;
  csv << "scene,width,height,config,decoupled,filter,bias,frame_ms_median,shadels_per_pixel,shade_memory_bytes,"
         "flip_mean,psnr,flicker,flicker_reference,flicker_excess\n";
  for (const auto& run : runs)
    for (const auto& c : run["configs"])
      csv << run["scene"].get<std::string>() << ',' << run["width"] << ',' << run["height"] << ','
          << c["config"].get<std::string>() << ',' << c["decoupled"] << ',' << c["filter"] << ','
          << (c["bias"].is_null() ? std::string("") : c["bias"].dump()) << ',' << c["frame_ms_median"] << ','
          << c["shadels_per_pixel"] << ',' << c["shade_memory_bytes"] << ',' << c["flip_mean"] << ',' << c["psnr"]
          << ',' << c["flicker"] << ',' << c["flicker_reference"] << ',' << c["flicker_excess"] << '\n';
  writeTextFile(file, "results", csv.str());
}

void runBench(const BenchArgs& args) {
  checkBenchArgs(args);
  const std::filesystem::path out = args.out;
  std::filesystem::create_directories(out);
  gpu::Context context;
  gpu::Device device(context);
  device.shaders().add(gpu::builtinShaders());
  if (args.effects) {
    runEffectsBench(context, device,
                    {.groups = args.effectGroups, .sizes = args.sizes, .repetitions = args.repetitions,
                     .lightCounts = args.lightCounts},
                    out);
    setExitCode(context.validationLog().count() ? 1 : 0);
    return;
  }
  if (args.sceneRatios) {
    runSceneRatioBench(context, device,
                       {.scenes = args.scenes, .sizes = args.sizes, .repetitions = args.repetitions,
                        .withoutOccludedSkip = args.withoutOccludedSkip},
                       out);
    setExitCode(context.validationLog().count() ? 1 : 0);
    return;
  }
  if (args.play > 0) {
    runPlaybackBench(context, device, {.scenes = args.scenes, .sizes = args.sizes, .frames = args.play}, out);
    setExitCode(context.validationLog().count() ? 1 : 0);
    return;
  }
  if (!args.materials.empty()) {
    runMaterialBench(context, device,
                     {.materials = args.materials, .scenes = args.scenes, .sizes = args.sizes,
                      .repetitions = args.repetitions, .referenceScale = args.referenceScale},
                     out);
    setExitCode(context.validationLog().count() ? 1 : 0);
    return;
  }
  if (!args.shadeRates.empty()) {
    runShadeRateBench(context, device,
                      {.rates = args.shadeRates, .scenes = args.scenes, .sizes = args.sizes,
                       .pathFrames = args.pathFrames, .movingObject = args.moveObject,
                       .budgets = args.shadeBudgets, .material = args.rateMaterial,
                       .unkeptLayers = args.unkeptLayers, .referenceScale = args.referenceScale,
                       .framesInFlight = args.framesInFlight},
                      out);
    setExitCode(context.validationLog().count() ? 1 : 0);
    return;
  }
  nlohmann::json runs = runPerSceneAndSize(args.scenes, args.sizes, [&](const std::string& scene, uint32_t w, uint32_t h) {
    return benchScene(device, scene, w, h, args, out);
  });
  if (args.shimmer) {
    uint32_t w = 0, h = 0;
    parseSize("--sizes", args.sizes.front(), w, h);
    runs.push_back(benchScene(device, "", w, h, args, out, shimmerCamera(), "shimmer"));
  }
  const nlohmann::json results{{"machine", machineJson(context)}, {"runs", runs}};
  writeTextFile(out / "results.json", "results", results.dump(2) + "\n");
  writeCsv(out / "results.csv", runs);
  std::printf("%-10s %-9s %-22s %9s %8s %8s %7s %9s\n", "scene", "size", "config", "frame ms", "shd/px", "FLIP",
              "PSNR", "flicker+");
  for (const auto& run : runs)
    for (const auto& c : run["configs"])
      std::printf("%-10s %4dx%-4d %-22s %9.2f %8.2f %8.4f %7.2f %9.5f\n", run["scene"].get<std::string>().c_str(),
                  run["width"].get<int>(), run["height"].get<int>(), c["config"].get<std::string>().c_str(),
                  c["frame_ms_median"].get<double>(), c["shadels_per_pixel"].get<double>(), c["flip_mean"].get<double>(),
                  c["psnr"].get<double>(), c["flicker_excess"].get<double>());
  // The shimmer case at equal frame time: forward against the decoupled
  // configuration whose median frame time is nearest to it.
  for (const auto& run : runs) {
    if (run["scene"] != "shimmer") continue;
    const auto& configs = run["configs"];
    const auto& forward = configs[0];
    const nlohmann::json* nearest = nullptr;
    for (const auto& c : configs)
      if (c["decoupled"].get<bool>() &&
          (!nearest || std::abs(c["frame_ms_median"].get<double>() - forward["frame_ms_median"].get<double>()) <
                           std::abs((*nearest)["frame_ms_median"].get<double>() - forward["frame_ms_median"].get<double>())))
        nearest = &c;
    if (nearest)
      std::printf("shimmer at equal time: forward %.1f ms flicker %.5f (reference %.5f); %s %.1f ms flicker %.5f\n",
                  forward["frame_ms_median"].get<double>(), forward["flicker"].get<double>(),
                  forward["flicker_reference"].get<double>(), (*nearest)["config"].get<std::string>().c_str(),
                  (*nearest)["frame_ms_median"].get<double>(), (*nearest)["flicker"].get<double>());
  }
  std::printf("wrote %s/results.json, results.csv and images\n", out.c_str());
  setExitCode(context.validationLog().count() ? 1 : 0);
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  static BenchArgs args;
  auto* cmd = app.add_subcommand("bench", "Measure what accuracy costs in time: configurations side by side");
  static GraphBenchArgs graphArgs;
  static TargetsBenchArgs targetsArgs;
  auto* graph = addBenchOptions(*cmd, args, graphArgs);
  auto* targets = addBenchTargetsOptions(*cmd, targetsArgs);
  cmd->callback([cmd] {
    if (cmd->got_subcommand("graph") || cmd->got_subcommand("targets")) return;
    runBench(args);
  });

  graph->callback([] { runGraphBench(graphArgs, args.out); });
  targets->callback([] { runTargetsBench(targetsArgs, args.out); });
}

}  // namespace sg::app
