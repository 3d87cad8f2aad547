// shadelgraph bench targets: issue 14's targets from one run. Four groups,
// each reusing another bench's measuring:
//   timed (per size): forward and decoupled of the default scene and
//     DamagedHelmet (decoupled also with shadel-mark rasterizing, against
//     which its work in the depth pre-pass is measured), the default scene
//     decoupled with the simplest material,
//     and the geometry-heavy models forward, all alternated round-robin
//     (bench_sessions.hpp) -> composite and shadel-mark ÷ forward-opaque, the
//     shade-space passes ÷ the decoupled frame, layer-shade ns per shadel, the
//     geometry-heavy forward frames;
//   cull (per size): the scene-ratio bench (bench_scenes.hpp) on cull-base,
//     cull-hidden, cull-offscreen -> hidden and off-screen ratios, both paths;
//   coverage (per size, no timing): every scene in auto mode, as render runs
//     it; the default scene, the named models and every sample model that goes
//     decoupled -> shadels per covered pixel, and PSNR against forward;
//   plans and graph (no timing of frames): transient heap bytes with and
//     without aliasing of the skin and bumps frames; bench graph's
//     declare + compile of 100 and 1000 synthetic passes.
#include "bench_targets.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include <builtin_shaders.hpp>
#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/graph/transient_peak.hpp>
#include <shadelgraph/image/metrics.hpp>

#include "bench_graph.hpp"
#include "bench_materials.hpp"
#include "bench_scenes.hpp"
#include "bench_sessions.hpp"
#include "bench_targets_table.hpp"
#include "commands.hpp"
#include "option_checks.hpp"
#include "output_file.hpp"
#include "scene_source.hpp"

namespace sg::app {
namespace {

const std::vector<std::string> kTimedSizes{"1280x720"};
const std::vector<std::string> kCoverageSizes{"640x360", "1280x720"};
const std::vector<std::string> kTimedScenes{"default", "DamagedHelmet"};
const std::vector<std::string> kCoverageNamed{"default", "DamagedHelmet", "Duck", "Suzanne"};
const std::vector<std::string> kGeometryModels{"MetalRoughSpheresNoTextures", "2CylinderEngine", "ReciprocatingSaw"};
const std::vector<std::string> kShadeSpacePasses{"shadel-clear",           "shadel-mask-clear", "shadel-mark",
                                                 "shadel-mark-requests",   "shadel-mark-neighbours",
                                                 "shadel-allocate",        "work-aggregate",    "support-expand"};
// shadel-mark's work in the depth pre-pass (its requests, drawn there) is the
// pre-pass's time over the same frame's with shadel-mark rasterizing (--mark raster).
double depthPassMarkMs(const BenchSession& requests, const BenchSession& raster) {
  const auto prepass = [](const BenchSession& s) { return s.passMedian("z-prepass") + s.passMedian("z-prepass (late)"); };
  return prepass(requests) - prepass(raster);
}
const std::vector<std::string> kCullScenes{"cull-base", "cull-hidden", "cull-offscreen"};
const std::vector<std::string> kAliasedMaterials{"skin", "bumps"};
// No near-empty material exists: the simplest debug one (a hash of the triangle ID, no texture, no light).
constexpr const char* kEmptyMaterial = "debug-triangle-id";
// What PSNR identical images are reported with (their PSNR is infinite, which JSON cannot hold).
constexpr double kIdenticalPsnr = 100.0;

struct Size {
  std::string text;
  uint32_t width = 0, height = 0;
};

std::vector<Size> parseSizes(const std::vector<std::string>& texts) {
  std::vector<Size> sizes;
  for (const auto& text : texts) {
    Size s{text};
    parseSize("--sizes", text, s.width, s.height);
    sizes.push_back(s);
  }
  return sizes;
}

// Where scenes come from, and which of them this run measures (--scenes).
class Scenes {
 public:
  explicit Scenes(const TargetsBenchArgs& args) : args_(args) {}

  bool selected(const std::string& name) const {
    return args_.scenes.empty() || std::find(args_.scenes.begin(), args_.scenes.end(), name) != args_.scenes.end();
  }
  // The path loadSceneArgument takes ("" for the default scene); empty and
  // `why` set when the scene is not measured.
  std::optional<std::string> path(const std::string& name, std::string& why) const {
    if (!selected(name)) {
      why = "not measured: not in --scenes";
      return std::nullopt;
    }
    if (name == "default") return std::string();
    const auto file = std::filesystem::path(args_.assets) / name / "glTF" / (name + ".gltf");
    if (!std::filesystem::is_regular_file(file)) {
      why = "skipped: " + file.string() + " not found";
      std::fprintf(stderr, "[bench] targets: %s %s\n", name.c_str(), why.c_str());
      return std::nullopt;
    }
    return file.string();
  }
  // Every sample model in the assets directory, by name.
  std::vector<std::string> sampleModels() const {
    std::vector<std::string> models;
    if (!std::filesystem::is_directory(args_.assets)) {
      std::fprintf(stderr, "[bench] targets: sample models skipped: %s not found\n", args_.assets.c_str());
      return models;
    }
    for (const auto& entry : std::filesystem::directory_iterator(args_.assets)) {
      const std::string name = entry.path().filename().string();
      if (std::filesystem::is_regular_file(entry.path() / "glTF" / (name + ".gltf"))) models.push_back(name);
    }
    std::sort(models.begin(), models.end());
    return models;
  }
  std::filesystem::path sceneFile(const std::string& name) const {
    return std::filesystem::path(args_.sceneFiles) / (name + ".json");
  }

 private:
  const TargetsBenchArgs& args_;
};

TargetFigure missing(const std::string& scene, const std::string& size, const std::string& detail,
                     const std::string& why) {
  return {.scene = scene, .size = size, .detail = detail, .note = why};
}

double ratioOrZero(double a, double b) { return b > 0.0 ? a / b : 0.0; }

// The rows, in the order; the groups below fill their figures.
struct Rows {
  TargetRow composite{.id = "composite_over_forward_opaque", .figure = "composite time ÷ forward-opaque time",
                      .scenes = "default scene, DamagedHelmet, 1280×720", .unit = "ratio", .target = 0.5};
  TargetRow mark{.id = "shadel_mark_over_forward_opaque", .figure = "shadel-mark time ÷ forward-opaque time",
                 .scenes = "default scene, DamagedHelmet, 1280×720", .unit = "ratio", .target = 0.25};
  TargetRow shadeSpace{.id = "shade_space_passes_over_decoupled_frame",
                       .figure = "DSE passes (clear, mark, allocate, aggregate, support-expand) ÷ decoupled frame",
                       .scenes = "default scene, DamagedHelmet, 1280×720", .unit = "ratio", .target = 0.08};
  TargetRow shadels{.id = "shadels_per_covered_pixel", .figure = "shadels shaded per covered pixel, default filter",
                    .scenes = "default scene, DamagedHelmet, Duck, Suzanne, every sample model that goes decoupled; "
                              "640×360 and 1280×720",
                    .unit = "shadels/px", .target = 1.5, .worstFirst = true};
  TargetRow layerShade{.id = "layer_shade_empty_material_ns_per_shadel",
                       .figure = "layer-shade with an empty material, ns per shadel", .scenes = "default scene",
                       .unit = "ns", .target = 30.0,
                       .note = std::string("no empty material exists: measured with ") + kEmptyMaterial +
                               " (a colour hashed from the triangle ID; no texture, no light) on every object"};
  TargetRow hidden{.id = "hidden_objects_frame_ratio", .figure = "frame with 10× hidden objects (behind a wall) ÷ without",
                   .scenes = "cull-hidden ÷ cull-base, forward and decoupled", .unit = "ratio", .target = 1.10};
  TargetRow offscreen{.id = "offscreen_objects_frame_ratio", .figure = "frame with 10× off-screen objects ÷ without",
                      .scenes = "cull-offscreen ÷ cull-base, forward and decoupled", .unit = "ratio", .target = 1.05};
  TargetRow aliasing{.id = "transient_bytes_aliased_over_unaliased", .figure = "transient bytes with aliasing ÷ without",
                     .scenes = "--material skin and --material bumps frames (default scene)", .unit = "ratio",
                     .target = 0.7, .note = "from the compiled plan's heaps, no frame rendered"};
  TargetRow graph100{.id = "graph_compile_100_passes_us", .figure = "graph declare+compile, 100 synthetic passes",
                     .scenes = "8 distinct synthetic graphs, fresh, reused and unchanged", .unit = "us", .target = 50.0};
  TargetRow graph1000{.id = "graph_compile_1000_over_100", .figure = "graph declare+compile, 1000 ÷ 100 synthetic passes",
                      .scenes = "8 distinct synthetic graphs, fresh, reused and unchanged", .unit = "ratio", .target = 10.0};
  TargetRow geometry{.id = "geometry_heavy_forward_frame_ms", .figure = "forward frame, geometry-heavy models ÷ before",
                     .scenes = "MetalRoughSpheresNoTextures, 2CylinderEngine, ReciprocatingSaw", .unit = "ms",
                     .target = 0.5, .relativeToBefore = true,
                     .note = "judged against --baseline-json's figure; without one, not judged"};
  TargetRow psnr{.id = "decoupled_vs_forward_psnr", .figure = "decoupled vs forward PSNR, sample models",
                 .scenes = "Suzanne and every sample model that goes decoupled", .unit = "dB",
                 .compare = TargetCompare::AtLeast, .target = 40.0, .worstFirst = true,
                 .note = "auto mode (what render runs) against forward, same view; identical images are given "
                         "100 dB"};

  std::vector<TargetRow> all() const {
    return {composite, mark, shadeSpace, shadels, layerShade, hidden, offscreen, aliasing, graph100, graph1000,
            geometry,  psnr};
  }
};

// Timed group: every configuration alternated in one round-robin per size.
void measureTimed(gpu::Device& device, const Scenes& scenes, const Size& size, int repetitions, Rows& rows) {
  struct PathPair {
    std::string scene;
    BenchSession forward, decoupled;
    BenchSession rasterMark;  // decoupled, shadel-mark rasterizing (what its work in the depth pre-pass is measured against)
  };
  std::vector<std::unique_ptr<PathPair>> pairs;
  std::unique_ptr<BenchSession> empty;
  std::vector<std::pair<std::string, std::unique_ptr<BenchSession>>> geometry;
  std::vector<BenchSession*> timed;
  const auto view = [&](BenchSession& s) {
    s.view = {.width = size.width, .height = size.height,
              .cameraOverride = s.renderer->camera({.width = size.width, .height = size.height})};
    timed.push_back(&s);
  };
  for (const auto& name : kTimedScenes) {
    std::string why;
    const auto path = scenes.path(name, why);
    if (!path) {
      for (auto* row : {&rows.composite, &rows.mark, &rows.shadeSpace})
        row->figures.push_back(missing(name, size.text, "", why));
      if (name == "default") rows.layerShade.figures.push_back(missing(name, size.text, kEmptyMaterial, why));
      continue;
    }
    const auto loaded = loadSceneArgument(*path);
    auto& pair = *pairs.emplace_back(std::make_unique<PathPair>());
    pair.scene = name;
    pair.forward.make(device, loaded.scene, scene::ShadingMode::Forward);
    pair.decoupled.make(device, loaded.scene, scene::ShadingMode::Decoupled);
    pair.rasterMark.make(device, loaded.scene, scene::ShadingMode::Decoupled, {.markRequests = false});
    view(pair.forward);
    view(pair.decoupled);
    view(pair.rasterMark);
    if (name == "default") {
      scene::Scene plain = loaded.scene;
      for (auto& instance : plain.instances) instance.material = kEmptyMaterial;
      empty = std::make_unique<BenchSession>();
      empty->make(device, plain, scene::ShadingMode::Decoupled);
      view(*empty);
    }
  }
  for (const auto& name : kGeometryModels) {
    std::string why;
    const auto path = scenes.path(name, why);
    if (!path) {
      rows.geometry.figures.push_back(missing(name, size.text, "forward", why));
      continue;
    }
    auto& [model, session] = geometry.emplace_back(name, std::make_unique<BenchSession>());
    session->make(device, loadSceneArgument(*path).scene, scene::ShadingMode::Forward);
    view(*session);
  }
  if (timed.empty()) return;
  std::fprintf(stderr, "[bench] targets %s: %zu timed configurations, %d rounds\n", size.text.c_str(), timed.size(),
               repetitions);
  alternateFrames(timed, repetitions);

  for (const auto& pair : pairs) {
    const double forwardOpaque = pair->forward.passMedian("forward-opaque");
    const double composite = pair->decoupled.passMedian("composite");
    // With its steps, where they run: the requests drawn in the depth pre-pass
    // and their merge, the chunk bits from the shadel masks.
    // A difference of two medians: in a small frame, where the requests cost
    // less than the timing noise, it can come out negative. Counted as 0 then
    // (the raw difference stays in the context).
    const double inDepthPassMeasured = depthPassMarkMs(pair->decoupled, pair->rasterMark);
    const double inDepthPass = std::max(0.0, inDepthPassMeasured);
    const double mark = inDepthPass + pair->decoupled.passMedian("shadel-mark") +
                        pair->decoupled.passMedian("shadel-mark-requests") +
                        pair->decoupled.passMedian("shadel-mark-neighbours");
    const nlohmann::json context{
        {"forward_opaque_ms", forwardOpaque},
        {"composite_ms", composite},
        {"shadel_mark_ms", mark},
        {"shadel_mark_in_depth_pass_ms", inDepthPass},
        {"shadel_mark_in_depth_pass_measured_ms", inDepthPassMeasured},
        {"forward_frame_ms", pair->forward.frameMedian()},
        {"decoupled_frame_ms", pair->decoupled.frameMedian()},
        {"raster_mark_frame_ms", pair->rasterMark.frameMedian()},
        {"raster_mark_ms", pair->rasterMark.passMedian("shadel-mark") + pair->rasterMark.passMedian("shadel-mark-neighbours")}};
    rows.composite.figures.push_back(
        {.scene = pair->scene, .size = size.text, .value = ratioOrZero(composite, forwardOpaque), .context = context});
    rows.mark.figures.push_back(
        {.scene = pair->scene, .size = size.text, .value = ratioOrZero(mark, forwardOpaque), .context = context});
    double shadeSpace = inDepthPass;
    nlohmann::json passes{{"shadel-mark in z-prepass", inDepthPass}};
    for (const auto& pass : kShadeSpacePasses) {
      passes[pass] = pair->decoupled.passMedian(pass);
      shadeSpace += passes[pass].get<double>();
    }
    rows.shadeSpace.figures.push_back({.scene = pair->scene, .size = size.text,
                                       .value = ratioOrZero(shadeSpace, pair->decoupled.frameMedian()),
                                       .context = {{"pass_ms", passes},
                                                   {"passes_ms", shadeSpace},
                                                   {"decoupled_frame_ms", pair->decoupled.frameMedian()}}});
  }
  if (empty) {
    const auto stats = empty->decoupled->stats();
    const double shaded = double(plugins::shadelsShaded(stats.counters));
    const double layerShade = empty->passMedian("layer-shade");
    // The row is absolute time, which follows this VM's speed from run to run:
    // tonemap (the same pixels every run) in the same frames tells how fast the machine was.
    TargetFigure f{.scene = "default", .size = size.text, .detail = kEmptyMaterial,
                   .context = {{"layer_shade_ms", layerShade},
                               {"shadels_shaded", shaded},
                               {"tonemap_ms_same_frames", empty->passMedian("tonemap")}}};
    if (shaded > 0.0) f.value = layerShade * 1e6 / shaded;
    else f.note = "no shadel shaded";
    rows.layerShade.figures.push_back(f);
  }
  for (const auto& [model, session] : geometry)
    rows.geometry.figures.push_back({.scene = model, .size = size.text, .detail = "forward",
                                     .value = session->frameMedian(),
                                     .context = {{"pass_ms", session->passMedians()}}});
}

// Cull group: the scene-ratio bench, forward and decoupled as now.
void measureCull(gpu::Device& device, const Scenes& scenes, const Size& size, int repetitions, Rows& rows) {
  const auto skip = [&](const std::string& why) {
    for (const char* path : {"forward", "decoupled"}) {
      rows.hidden.figures.push_back(missing("cull-hidden", size.text, path, why));
      rows.offscreen.figures.push_back(missing("cull-offscreen", size.text, path, why));
    }
  };
  if (!scenes.selected("cull")) return skip("not measured: not in --scenes");
  std::vector<LoadedScene> loaded;
  for (const auto& name : kCullScenes) {
    const auto file = scenes.sceneFile(name);
    try {
      loaded.push_back(loadSceneArgument(file.string()));
    } catch (const std::exception& e) {  // absent, or its models absent
      std::fprintf(stderr, "[bench] targets: cull scenes skipped: %s\n", e.what());
      return skip(std::string("skipped: ") + e.what());
    }
  }
  const nlohmann::json run = measureSceneRatios(device, loaded, kCullScenes, size.width, size.height, repetitions,
                                                /*withBefore=*/false);
  for (const auto& c : run["configs"]) {
    const std::string scene = c["scene"];
    if (scene == "cull-base") continue;
    auto& row = scene == "cull-hidden" ? rows.hidden : rows.offscreen;
    row.figures.push_back({.scene = scene, .size = size.text, .detail = c["config"].get<std::string>(),
                           .value = c["ratio_to_first"].get<double>(),
                           .context = {{"frame_ms", c["frame_ms_median"]}, {"pass_ms", c["pass_ms_median"]}}});
  }
}

// Coverage group: each scene as render runs it (auto mode) against forward.
void measureCoverage(gpu::Device& device, const Scenes& scenes, const std::vector<Size>& sizes, int frames,
                     Rows& rows) {
  std::vector<std::string> candidates{"default"};
  for (const auto& model : scenes.sampleModels()) candidates.push_back(model);
  for (const auto& named : kCoverageNamed)
    if (std::find(candidates.begin(), candidates.end(), named) == candidates.end()) candidates.push_back(named);
  std::vector<std::string> forwardOnly, unloadable;
  for (const auto& name : candidates) {
    const bool named = std::find(kCoverageNamed.begin(), kCoverageNamed.end(), name) != kCoverageNamed.end();
    std::string why;
    const auto path = scenes.path(name, why);
    if (!path) {
      if (!named) continue;  // a sample model not selected
      for (const auto& size : sizes) {
        rows.shadels.figures.push_back(missing(name, size.text, "", why));
        if (name != "default") rows.psnr.figures.push_back(missing(name, size.text, "", why));
      }
      continue;
    }
    std::fprintf(stderr, "[bench] targets: %s in auto mode\n", name.c_str());
    LoadedScene loaded;
    auto session = std::make_unique<BenchSession>();
    try {
      loaded = loadSceneArgument(*path);
      session->make(device, loaded.scene, std::nullopt);
    } catch (const std::exception& e) {  // one model that does not load does not end the run
      std::fprintf(stderr, "[bench] targets: %s skipped: %s\n", name.c_str(), e.what());
      unloadable.push_back(name + " (" + e.what() + ")");
      for (const auto& size : sizes)
        if (named) {
          rows.shadels.figures.push_back(missing(name, size.text, "", std::string("skipped: ") + e.what()));
          if (name != "default") rows.psnr.figures.push_back(missing(name, size.text, "", std::string("skipped: ") + e.what()));
        }
      continue;
    }
    // A named scene that auto mode shades forward is measured in mode decoupled (automatic chart), as the issue did.
    std::string detail;
    std::unique_ptr<BenchSession> forward;
    for (size_t i = 0; i < sizes.size(); ++i) {
      const auto& size = sizes[i];
      const render::RenderSettings view{.width = size.width, .height = size.height,
                                        .cameraOverride = session->renderer->camera({.width = size.width, .height = size.height})};
      render::FrameResult frame;
      const auto settle = [&] {
        for (int f = 0; f < frames; ++f) frame = session->renderer->render(view);  // the adjuster settles
      };
      settle();
      // Auto mode decides per frame (tiny objects, minified textures without
      // mip levels), so a sample model may be forward at one size only.
      if (!named && session->decoupled->stats().objects == 0) {
        forwardOnly.push_back(name + " at " + size.text);
        continue;
      }
      if (i == 0 && session->decoupled->stats().objects == 0) {
        std::fprintf(stderr, "[bench] targets: %s is forward in auto mode: measured in mode decoupled\n", name.c_str());
        detail = "mode decoupled (auto: forward)";
        session = std::make_unique<BenchSession>();
        session->make(device, loaded.scene, scene::ShadingMode::Decoupled);
        settle();
      }
      const auto stats = session->decoupled->stats();
      if (stats.objects == 0) {
        const std::string none = "no object goes decoupled, even in mode decoupled";
        rows.shadels.figures.push_back(missing(name, size.text, detail, none));
        if (name != "default") rows.psnr.figures.push_back(missing(name, size.text, detail, none));
        continue;
      }
      rows.shadels.figures.push_back({.scene = name, .size = size.text, .detail = detail,
                                      .value = plugins::shadelsPerCoveredPixel(stats.counters),
                                      .context = {{"decoupled_objects", stats.objects},
                                                  {"covered_pixels", stats.counters.coveredPixels},
                                                  {"global_bias", stats.bias}}});
      if (name == "default") continue;  // the PSNR row is the sample models'
      if (!forward) {
        forward = std::make_unique<BenchSession>();
        forward->make(device, loaded.scene, scene::ShadingMode::Forward);
      }
      const auto reference = forward->renderer->render(view);
      const auto diff = image::compareRgba8(reference.image.rgba8, frame.image.rgba8);
      TargetFigure f{.scene = name, .size = size.text, .detail = detail, .context = {{"decoupled_objects", stats.objects}}};
      f.value = std::isfinite(diff.psnr) ? diff.psnr : kIdenticalPsnr;
      if (!std::isfinite(diff.psnr)) f.note = "identical images";
      rows.psnr.figures.push_back(f);
    }
  }
  const auto join = [](const std::vector<std::string>& names) {
    std::string list;
    for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
    return list;
  };
  std::string note;
  if (!forwardOnly.empty()) note += "forward in auto mode, so not listed: " + join(forwardOnly);
  if (!unloadable.empty()) note += std::string(note.empty() ? "" : "; ") + "not loaded: " + join(unloadable);
  if (!note.empty()) {
    rows.shadels.note = note;
    rows.psnr.note += "; " + note;
  }
}

// Transient heap bytes of a frame's compiled plan, with aliasing ÷ without.
void measureAliasing(gpu::Device& device, const Scenes& scenes, const Size& size, Rows& rows) {
  for (const auto& material : kAliasedMaterials) {
    std::string why;
    const auto path = scenes.path("default", why);
    if (!path) {
      rows.aliasing.figures.push_back(missing("default", size.text, material, why));
      continue;
    }
    BenchSession session;
    scene::Scene withMaterial = loadSceneArgument(*path).scene;
    for (auto& instance : withMaterial.instances) instance.material = material;
    session.make(device, withMaterial, std::nullopt);
    const auto plan = session.renderer->plan({.width = size.width, .height = size.height});
    // Where the transients need the most bytes at once: no packing gets the
    // aliased heaps below that, so peak ÷ without aliasing is the figure's floor
    // for this frame's resources and lifetimes.
    const graph::TransientPeak peak = graph::transientPeak(plan);
    nlohmann::json live = nlohmann::json::object();
    for (const auto& r : peak.live) live[r.name] = live.value(r.name, uint64_t{0}) + r.bytes;
    TargetFigure f{.scene = "default", .size = size.text, .detail = material,
                   .context = {{"heap_bytes", plan.heapBytes},
                               {"heap_bytes_without_aliasing", plan.heapBytesWithoutAliasing},
                               {"peak_pass", peak.pass},
                               {"peak_bytes", peak.bytes},
                               {"peak_live_bytes", live},
                               {"floor", ratioOrZero(double(peak.bytes), double(plan.heapBytesWithoutAliasing))}}};
    if (plan.heapBytesWithoutAliasing > 0) f.value = double(plan.heapBytes) / double(plan.heapBytesWithoutAliasing);
    else f.note = "no transient heaps";
    rows.aliasing.figures.push_back(f);
  }
}

nlohmann::json measureGraphSizes(int repetitions) {
  return measureGraphCompile({.passes = {100, 1000}, .graphs = 8, .repetitions = uint32_t(8 * repetitions)});
}

// Judged after the frames, as a frame's compile follows the frame's work;
// `beforeFrames` (the same measuring before any GPU work) goes into the context:
// after the frames every mode takes about 6 us longer (docs/benchmarks.md).
void measureGraph(int repetitions, const nlohmann::json& beforeFrames, Rows& rows) {
  const nlohmann::json measured = measureGraphSizes(repetitions);
  const auto& sizes = measured["sizes"];
  for (const char* mode : {"fresh", "reused", "unchanged"}) {
    nlohmann::json context = sizes[0][mode];
    context["median_us_before_frames"] = beforeFrames["sizes"][0][mode]["median_us"];
    rows.graph100.figures.push_back({.scene = "synthetic", .detail = mode,
                                     .value = sizes[0][mode]["median_us"].get<double>(),
                                     .context = context});
    rows.graph1000.figures.push_back({.scene = "synthetic", .detail = mode,
                                      .value = measured["ratios"][0][mode].get<double>(),
                                      .context = {{"median_us_100", sizes[0][mode]["median_us"]},
                                                  {"median_us_1000", sizes[1][mode]["median_us"]}}});
  }
}

void printSummary(const nlohmann::json& targets) {
  std::printf("%-44s %10s %14s  %s\n", "target", "worst", "target", "met");
  for (const auto& row : targets["rows"]) {
    char worst[32] = "-", target[48];
    if (row["worst"].is_number()) std::snprintf(worst, sizeof worst, "%.4g", row["worst"].get<double>());
    std::snprintf(target, sizeof target, "%s %g%s", row["compare"].get<std::string>().c_str(),
                  row["target"].get<double>(), row["relative_to_before"].get<bool>() ? "x before" : "");
    std::printf("%-44s %10s %14s  %s\n", row["id"].get<std::string>().c_str(), worst, target,
                row["met"].is_null() ? "not judged" : row["met"].get<bool>() ? "met" : "NOT met");
  }
}

}  // namespace

void runTargetsBench(const TargetsBenchArgs& args, const std::filesystem::path& out) {
  checkBenchTargetsArgs(args);
  nlohmann::json baseline;
  if (!args.baselineJson.empty()) {
    std::ifstream in(args.baselineJson);
    if (!in) throw std::runtime_error("--baseline-json: cannot read " + args.baselineJson);
    baseline = nlohmann::json::parse(in, nullptr, false);
    if (baseline.is_discarded() || !baseline.is_object() || !baseline.contains("rows") || !baseline["rows"].is_array())
      throw std::runtime_error("--baseline-json " + args.baselineJson + ": not a targets.json (no \"rows\" array)");
  }
  std::filesystem::create_directories(out);
  const nlohmann::json graphBeforeFrames = measureGraphSizes(args.repetitions);
  gpu::Context context;
  gpu::Device device(context);
  device.shaders().add(gpu::builtinShaders());
  const Scenes scenes(args);
  const auto timedSizes = parseSizes(args.sizes.empty() ? kTimedSizes : args.sizes);
  const auto coverageSizes = parseSizes(args.sizes.empty() ? kCoverageSizes : args.sizes);
  Rows rows;
  // Each group's wall time on stderr: where a run's time goes.
  const auto timedGroup = [](const char* name, const std::function<void()>& run) {
    const auto start = std::chrono::steady_clock::now();
    run();
    std::fprintf(stderr, "[bench] targets: %s took %.1f s\n", name,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  };
  for (const auto& size : timedSizes) {
    timedGroup("timed", [&] { measureTimed(device, scenes, size, args.repetitions, rows); });
    timedGroup("cull", [&] { measureCull(device, scenes, size, args.repetitions, rows); });
    timedGroup("aliasing", [&] { measureAliasing(device, scenes, size, rows); });
  }
  timedGroup("coverage", [&] { measureCoverage(device, scenes, coverageSizes, args.repetitions + 1, rows); });
  timedGroup("graph", [&] { measureGraph(args.repetitions, graphBeforeFrames, rows); });

  std::vector<TargetRow> all = rows.all();
  if (!baseline.is_null()) applyBaseline(all, baseline);
  nlohmann::json header{{"machine", machineJson(context)},
                        {"repetitions", args.repetitions},
                        {"baseline", args.baselineJson.empty() ? nlohmann::json(nullptr) : nlohmann::json(args.baselineJson)}};
  const nlohmann::json targets = targetsJson(std::move(all), header);
  writeTextFile(out / "targets.json", "results", targets.dump(2) + "\n");
  writeTextFile(out / "targets.md", "results", targetsMarkdown(targets));
  printSummary(targets);
  std::printf("wrote %s/targets.json and targets.md\n", out.c_str());
  setExitCode(context.validationLog().count() ? 1 : 0);
}

}  // namespace sg::app
