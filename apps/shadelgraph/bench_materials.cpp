// shadelgraph bench --materials a,b,c: what each material costs. For each
// scene and size, every material runs forward and decoupled (trilinear, the
// adjuster on): all sessions are set up first, then frames alternate
// round-robin across every (material, path) configuration, one warm-up round
// and --repetitions timed rounds; medians are reported. Error: against the
// forward render of the same material at referenceScale² samples per pixel.
// Materials with persistent layers also get cold frames (nothing to reuse,
// pipelines warm): what the reuse saves.
#include "bench_materials.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <map>
#include <memory>

#include <builtin_materials.hpp>
#include <builtin_plugins.hpp>
#include <decoupled/decoupled_package.hpp>
#include <shadelgraph/image/flip.hpp>
#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/render/renderer.hpp>

#include "bench_sessions.hpp"
#include "output_file.hpp"
#include "scene_source.hpp"

namespace sg::app {
namespace {

struct MaterialConfig {
  std::string material;
  bool decoupled = false;
  std::string path() const { return decoupled ? "decoupled" : "forward"; }
  std::string name() const { return material + " " + path(); }
};

struct Session {
  scene::Scene scene;
  std::shared_ptr<plugins::DecoupledShading> decoupled;
  std::unique_ptr<render::Renderer> renderer;
};

double reuseFraction(const plugins::LayerReuse& r) {
  const uint64_t total = r.reused + r.computed;
  return total ? double(r.reused) / double(total) : 0.0;
}

// All layer-shade passes of a frame ("layer-shade", "layer-shade #2", ...).
double layerShadeTotalMs(const gpu::FrameTimings& timings) {
  double sum = 0.0;
  for (const auto& p : timings.passes)
    if (p.name.rfind("layer-shade", 0) == 0) sum += p.gpuMs;
  return sum;
}

// What a configuration's frames measured, one sample per frame.
struct Samples {
  std::vector<double> frameMs, gpuMs, layerShadeMs;
  std::map<std::string, std::vector<double>> passMs, reuse;  // reuse: per persistent layer

  void add(const render::FrameResult& frame, const plugins::DecoupledStats& stats) {
    frameMs.push_back(frame.timings.frameMs);
    gpuMs.push_back(frame.timings.gpuMs);
    layerShadeMs.push_back(layerShadeTotalMs(frame.timings));
    for (const auto& p : frame.timings.passes) passMs[p.name].push_back(p.gpuMs);
    for (const auto& r : stats.layerReuse) reuse[r.layer].push_back(reuseFraction(r));
  }
  nlohmann::json passMedians() const { return medians(passMs); }
  nlohmann::json reuseMedians() const { return medians(reuse); }
};

// A camera that sees none of the scene: outside its bounds, looking away. A
// frame through it runs no persistent layer, so the next has nothing to reuse.
scene::Camera awayCamera(scene::Camera camera, const scene::Scene& s) {
  const scene::Bounds bounds = scene::worldBounds(s);
  glm::vec3 direction = camera.position() - bounds.center();
  direction.y = 0.0f;  // horizontal: lookAtWorld needs a direction off the up axis
  direction = glm::length(direction) > 1e-6f ? glm::normalize(direction) : glm::vec3(0.0f, 0.0f, 1.0f);
  const glm::vec3 eye = bounds.center() + direction * (4.0f * bounds.radius() + 1.0f);
  camera.world = scene::lookAtWorld(eye, eye + direction);
  return camera;
}

// The median of all layer-shade passes ÷ the shadels they shaded (64 per chunk
// shaded: every invocation of the chunk's workgroup, on the object or not), in ns.
double layerShadeNsPerShadel(double layerShadeMs, uint64_t shadels) {
  return shadels ? layerShadeMs * 1e6 / double(shadels) : 0.0;
}

double passMedian(const nlohmann::json& config, const char* pass) {
  const auto& passes = config["pass_ms_median"];
  return passes.contains(pass) ? passes[pass].get<double>() : 0.0;
}

nlohmann::json benchMaterials(gpu::Device& device, const std::string& scenePath, uint32_t width, uint32_t height,
                              const MaterialBenchArgs& args, const std::filesystem::path& out) {
  const auto loaded = loadSceneArgument(scenePath);
  const std::string sceneName = scenePath.empty() ? "default" : std::filesystem::path(scenePath).stem().string();
  const std::string tag = sceneName + "-" + std::to_string(width);
  const auto& registry = plugins::builtinRegistry();

  // Forward and decoupled of every material, adjacent: configs[2m], configs[2m + 1].
  std::vector<MaterialConfig> configs;
  for (const auto& material : args.materials) {
    registry.material(material);  // an unknown name fails here, listing the known ones
    configs.push_back({material, false});
    configs.push_back({material, true});
  }
  std::vector<Session> sessions(configs.size());
  for (size_t c = 0; c < configs.size(); ++c) {
    auto& s = sessions[c];
    s.scene = loaded.scene;
    for (auto& instance : s.scene.instances) instance.material = configs[c].material;
    const auto mode = configs[c].decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward;
    auto made = plugins::makeDecoupledRenderer(device, s.scene, registry, mode, plugins::DecoupledSettings{.filter = 2});
    s.decoupled = std::move(made.shading);
    s.renderer = std::move(made.renderer);
  }
  const scene::Camera camera = sessions[0].renderer->camera({.width = width, .height = height});
  const render::RenderSettings view{.width = width, .height = height, .cameraOverride = camera};

  // Timing: configurations alternate inside each round; the first round is
  // the warm-up (pipelines, the adjuster) and, for persistent layers, the
  // frame with nothing to reuse yet. That frame also compiles, so each timed
  // round adds, for every configuration with persistent layers, a cold frame
  // after a frame that saw nothing: the same work as the first frame, warm,
  // alternated with the rest so drift affects it alike.
  std::fprintf(stderr, "[bench] %s %ux%u: %zu material configurations, %d rounds\n", sceneName.c_str(), width, height,
               configs.size(), args.repetitions);
  const render::RenderSettings away{.width = width, .height = height, .cameraOverride = awayCamera(camera, loaded.scene)};
  std::vector<Samples> timed(configs.size()), first(configs.size()), cold(configs.size());
  std::vector<render::FrameResult> lastFrame(configs.size());
  std::vector<plugins::DecoupledStats> lastStats(configs.size());
  std::vector<bool> persistent(configs.size(), false);
  for (int rep = -1; rep < args.repetitions; ++rep)
    for (size_t c = 0; c < configs.size(); ++c) {
      auto frame = sessions[c].renderer->render(view);
      const auto stats = sessions[c].decoupled->stats();
      (rep < 0 ? first : timed)[c].add(frame, stats);
      if (rep < 0) persistent[c] = configs[c].decoupled && !stats.layerReuse.empty();
      lastFrame[c] = std::move(frame);
      lastStats[c] = stats;
      if (rep >= 0 && persistent[c]) {
        sessions[c].renderer->render(away);
        const auto coldFrame = sessions[c].renderer->render(view);
        cold[c].add(coldFrame, sessions[c].decoupled->stats());
      }
    }

  // Error: against the forward render of the same material, supersampled.
  const uint32_t scale = uint32_t(args.referenceScale);
  nlohmann::json results = nlohmann::json::array();
  for (size_t m = 0; m < args.materials.size(); ++m) {
    const std::string& material = args.materials[m];
    std::fprintf(stderr, "[bench] %s %ux%u: %s reference (%d spp)\n", sceneName.c_str(), width, height,
                 material.c_str(), args.referenceScale * args.referenceScale);
    const auto reference = downsample(
        sessions[2 * m].renderer->render({.width = width * scale, .height = height * scale, .cameraOverride = camera}).image,
        scale);
    image::writePng(out / (tag + "-" + material + "-reference.png"), width, height, reference.pixels.data());
    for (size_t c = 2 * m; c < 2 * m + 2; ++c) {
      const auto& config = configs[c];
      const auto& stats = lastStats[c];
      const auto test = toImage(lastFrame[c].image);
      const auto flip = image::flipLdr(reference, test);
      const auto diff = image::compareRgba8(reference.pixels, test.pixels);
      const std::string file = tag + "-" + material + "-" + config.path() + ".png";
      image::writePng(out / file, test.width, test.height, test.pixels.data());
      image::writePng(out / ("flip-" + file), width, height, image::flipHeatmap(flip).pixels.data());
      const auto path = config.decoupled ? plugin::ShadingPath::Decoupled : plugin::ShadingPath::Forward;
      const auto& run = registry.materialFor(material, path);
      nlohmann::json persistentJson = nullptr;
      if (!cold[c].gpuMs.empty()) {
        const double coldMs = median(cold[c].layerShadeMs), steadyMs = median(timed[c].layerShadeMs);
        persistentJson = {{"first_frame", {{"layer_shade_ms", first[c].layerShadeMs[0]},
                                           {"gpu_ms", first[c].gpuMs[0]},
                                           {"pass_ms", first[c].passMedians()},
                                           {"layer_reuse", first[c].reuseMedians()}}},
                          {"cold", {{"layer_shade_ms_median", coldMs},
                                    {"gpu_ms_median", median(cold[c].gpuMs)},
                                    {"pass_ms_median", cold[c].passMedians()},
                                    {"layer_reuse", cold[c].reuseMedians()},
                                    {"frames", cold[c].gpuMs.size()}}},
                          {"steady", {{"layer_shade_ms_median", steadyMs},
                                      {"gpu_ms_median", median(timed[c].gpuMs)},
                                      {"layer_reuse", timed[c].reuseMedians()}}},
                          {"payoff_ms", coldMs - steadyMs}};
      }
      results.push_back(
          {{"config", config.name()},
           {"material", material},
           {"path", config.path()},
           {"material_run", run.name},  // the forward fallback, when the material has decoupled-only layers
           {"layers", config.decoupled ? nlohmann::json(stats.layers) : nlohmann::json(run.layers)},
           {"frame_ms_median", median(timed[c].frameMs)},
           {"frame_ms_samples", timed[c].frameMs},
           {"gpu_ms_median", median(timed[c].gpuMs)},
           {"gpu_ms_samples", timed[c].gpuMs},
           {"pass_ms_median", timed[c].passMedians()},
           {"layer_shade_ms_median", median(timed[c].layerShadeMs)},
           {"shadels_shaded", config.decoupled ? plugins::shadelsShaded(stats.counters) : 0ull},
           {"layer_shade_ns_per_shadel",
            config.decoupled ? layerShadeNsPerShadel(median(timed[c].layerShadeMs), plugins::shadelsShaded(stats.counters))
                             : 0.0},
           {"layer_dispatches", stats.layerDispatches},
           {"layer_reuse", timed[c].reuseMedians()},
           {"history_bytes", stats.historyBytes},
           {"transient_bytes", lastFrame[c].transientBytes},
           {"shade_memory_bytes", config.decoupled ? stats.storageBytes + stats.remapBytes + stats.idMapBytes : 0},
           {"shadels_per_pixel", plugins::shadelsPerCoveredPixel(stats.counters)},
           {"support_chunks", stats.counters.supportChunks},
           {"overflow_chunks", stats.counters.overflowChunks},
           {"composite_misses", stats.counters.compositeMisses},
           {"flip_mean", flip.mean},
           {"psnr", diff.psnr},
           {"image", file},
           {"persistent", persistentJson}});
    }
  }
  return {{"scene", sceneName}, {"width", width}, {"height", height}, {"repetitions", args.repetitions},
          {"reference_spp", args.referenceScale * args.referenceScale}, {"configs", results}};
}

void writeCsv(const std::filesystem::path& file, const nlohmann::json& runs) {
  std::ostringstream csv;
  csv << "scene,width,height,material,path,material_run,frame_ms_median,gpu_ms_median,layer_shade_ms,"
         "layer_shade_2_ms,layer_shade_3_ms,support_expand_ms,layer_dispatches,history_bytes,transient_bytes,"
         "shade_memory_bytes,flip_mean,psnr,first_frame_layer_shade_ms,cold_layer_shade_ms,steady_layer_shade_ms,"
         "shadels_shaded,layer_shade_ns_per_shadel\n";
  for (const auto& run : runs)
    for (const auto& c : run["configs"]) {
      const auto& p = c["persistent"];
      csv << run["scene"].get<std::string>() << ',' << run["width"] << ',' << run["height"] << ','
          << c["material"].get<std::string>() << ',' << c["path"].get<std::string>() << ','
          << c["material_run"].get<std::string>() << ',' << c["frame_ms_median"] << ',' << c["gpu_ms_median"] << ','
          << passMedian(c, "layer-shade") << ',' << passMedian(c, "layer-shade #2") << ','
          << passMedian(c, "layer-shade #3") << ',' << passMedian(c, "support-expand") << ','
          << c["layer_dispatches"] << ',' << c["history_bytes"] << ',' << c["transient_bytes"] << ','
          << c["shade_memory_bytes"] << ',' << c["flip_mean"] << ',' << c["psnr"] << ','
          << (p.is_null() ? "" : p["first_frame"]["layer_shade_ms"].dump()) << ','
          << (p.is_null() ? "" : p["cold"]["layer_shade_ms_median"].dump()) << ','
          << (p.is_null() ? "" : p["steady"]["layer_shade_ms_median"].dump()) << ',' << c["shadels_shaded"] << ','
          << c["layer_shade_ns_per_shadel"] << '\n';
    }
  writeTextFile(file, "results", csv.str());
}

void printTable(const nlohmann::json& runs) {
  constexpr double MiB = 1 << 20;
  std::printf("%-8s %-8s %-9s %-9s %8s %8s %7s %8s %8s %8s %7s %9s %4s %7s %7s %7s %6s\n", "scene", "size",
              "material", "path", "GPU ms", "frame ms", "dec/fwd", "shade#1", "shade#2", "shade#3", "expand",
              "ns/shadel", "disp", "histMiB", "tranMiB", "FLIP", "PSNR");
  for (const auto& run : runs) {
    const auto& configs = run["configs"];
    for (size_t i = 0; i < configs.size(); ++i) {
      const auto& c = configs[i];
      const bool decoupled = c["path"] == "decoupled";
      // configs alternate forward, decoupled per material
      const double ratio = decoupled ? c["gpu_ms_median"].get<double>() / configs[i - 1]["gpu_ms_median"].get<double>() : 1.0;
      std::printf("%-8s %4dx%-3d %-9s %-9s %8.2f %8.2f %7.2f %8.2f %8.2f %8.2f %7.2f %9.1f %4d %7.2f %7.2f %7.4f %6.2f\n",
                  run["scene"].get<std::string>().c_str(), run["width"].get<int>(), run["height"].get<int>(),
                  c["material"].get<std::string>().c_str(), c["path"].get<std::string>().c_str(),
                  c["gpu_ms_median"].get<double>(), c["frame_ms_median"].get<double>(), ratio,
                  passMedian(c, "layer-shade"), passMedian(c, "layer-shade #2"), passMedian(c, "layer-shade #3"),
                  passMedian(c, "support-expand"), c["layer_shade_ns_per_shadel"].get<double>(),
                  c["layer_dispatches"].get<int>(),
                  c["history_bytes"].get<double>() / MiB, c["transient_bytes"].get<double>() / MiB,
                  c["flip_mean"].get<double>(), c["psnr"].is_number() ? c["psnr"].get<double>() : 0.0);
    }
    for (const auto& c : configs) {
      const auto& p = c["persistent"];
      if (p.is_null()) continue;
      const auto& firstPasses = p["first_frame"]["pass_ms"];
      std::printf("%s %s: layer-shade first frame %.2f ms, cold %.2f ms, steady %.2f ms; all layer-shade passes "
                  "%.2f, %.2f, %.2f ms; reuse",
                  run["scene"].get<std::string>().c_str(), c["config"].get<std::string>().c_str(),
                  firstPasses.value("layer-shade", 0.0), p["cold"]["pass_ms_median"].value("layer-shade", 0.0),
                  passMedian(c, "layer-shade"), p["first_frame"]["layer_shade_ms"].get<double>(),
                  p["cold"]["layer_shade_ms_median"].get<double>(), p["steady"]["layer_shade_ms_median"].get<double>());
      for (const auto& [layer, fraction] : p["steady"]["layer_reuse"].items())
        std::printf(" %s %.3f (cold %.3f)", layer.c_str(), fraction.get<double>(),
                    p["cold"]["layer_reuse"].value(layer, 0.0));
      std::printf("; saves %.2f ms per frame\n", p["payoff_ms"].get<double>());
    }
  }
}

}  // namespace

void runMaterialBench(gpu::Context& context, gpu::Device& device, const MaterialBenchArgs& args,
                      const std::filesystem::path& out) {
  const nlohmann::json runs =
      runPerSceneAndSize(args.scenes, args.sizes, [&](const std::string& scene, uint32_t w, uint32_t h) {
        return benchMaterials(device, scene, w, h, args, out);
      });
  const nlohmann::json results{{"machine", machineJson(context)}, {"runs", runs}};
  writeTextFile(out / "materials.json", "results", results.dump(2) + "\n");
  writeCsv(out / "materials.csv", runs);
  printTable(runs);
  std::printf("wrote %s/materials.json, materials.csv and images\n", out.c_str());
}

}  // namespace sg::app
