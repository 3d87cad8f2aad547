#include "command_options.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <shadelgraph/shadel/shadel_storage.hpp>

#include "option_checks.hpp"

namespace sg::app {
namespace {

// Option limits, named in --help and in the errors.
constexpr double kMinStorage = shadel::kMinStorageFactor, kMaxStorage = 64.0;
constexpr double kMaxAbsBias = 8.0;
constexpr int kMaxFrames = 100'000'000;
constexpr int kMaxShadeRate = 1'000'000;
constexpr double kMaxSeconds = 1e9;  // --time: about 30 years, still exact to the millisecond in double

// The scene, output size and shading mode, as render and graph take them.
void addSceneOptions(CLI::App& command, std::string& scene, std::string& size, std::string& mode) {
  command.add_option("scene", scene, "a .gltf/.glb/.json scene (default: the built-in scene)");
  command.add_option("--size", size, "WIDTHxHEIGHT, each side 1 to " + std::to_string(kMaxOutputSide))
      ->capture_default_str();
  command.add_option("--mode", mode, "shading of every object: forward, decoupled, auto (default: each object's own)")
      ->check(CLI::IsMember({"forward", "decoupled", "auto"}));
}

}  // namespace

std::vector<std::string> MaterialArgs::paths() const {
  std::vector<std::string> all = directories;
  all.insert(all.end(), libraries.begin(), libraries.end());
  return all;
}

void addMaterialOptions(CLI::App& command, MaterialArgs& args) {
  // Existence is checked by the loader, whose messages name the plugin.
  command.add_option("--plugin", args.libraries, "load a plugin library (.so); repeatable");
  command.add_option("--plugin-dir", args.directories, "load every plugin (*.so) of a directory; repeatable");
  command.add_option("--material", args.material,
                     "material (layer stack) of every object, e.g. bumps, skin, marble, debug-uv-checker, or a "
                     "plugin's (default: the scene's, else gltf-pbr)");
}

void addFrameOptions(CLI::App& command, FrameArgs& args) {
  command.add_option("--frame-graph", args.frameGraph,
                     "the frame: a registered frame's name (forward, decoupled, a plugin's) or a JSON frame "
                     "description (docs/composing-frames.md); default: decoupled");
  command.add_option("--object-mode", args.objectModes,
                     "NAME=forward|decoupled|auto: one object's shading mode, over --mode; repeatable");
}

void addFrameSetupOptions(CLI::App& command, RenderArgs& args) {
  addSceneOptions(command, args.scene, args.size, args.mode);
  auto* camera = command.add_option_function<int>(
      "--camera", [&args](const int& index) { args.camera = index; },
      "camera index of the scene, 0 or more (default: its first, else framing)");
  command.add_option_function<int>(
         "--frame", [&args](const int& frame) { args.frame = frame; },
         "frame along a camera path of the scene file (30 per second), 0 or more")
      ->excludes(camera);
  command.add_option("--path", args.path, "which camera path --frame follows")->capture_default_str();
  command.add_option("--filter", args.filter, "decoupled composite filter: 0 point, 1 bilinear, 2 trilinear")
      ->check(CLI::Range(0, 2))
      ->capture_default_str();
  command.add_option("--view", args.view, "final, or a debug view of decoupled shading: level, occupancy, sheet")
      ->check(CLI::IsMember({"final", "level", "occupancy", "sheet"}))
      ->capture_default_str();
  command.add_option_function<double>(
      "--bias", [&args](const double& bias) { args.bias = bias; },
      "fixed global level bias, -8 to 8; below 0 finer shadels, above 0 coarser (default: the shade-space adjuster "
      "decides)");
  command.add_option("--storage", args.storage, "shade storage in shadels per output pixel, 1.25 to 64")
      ->capture_default_str();
  command.add_option("--shade-rate", args.shadeRate,
                     "a shade frame (every visible chunk shaded) every N raster frames, 1 or more; the frames between "
                     "shade only what has no shading from the frame before and reuse the rest (1: every frame)")
      ->capture_default_str();
  command.add_option("--frames-in-flight", args.framesInFlight,
                     "1 or 2; 2 with --shade-rate above 1: the shade frame runs on async compute after its raster "
                     "frame's composite, as the next raster frame is recorded, and later frames read it")
      ->capture_default_str();
  auto* budget = command.add_option_function<double>(
      "--shade-budget", [&args](const double& ms) { args.shadeBudget = ms; },
      "budget mode: no shade frames; each frame fills what is missing, then reshades the stalest chunks this many "
      "milliseconds of layer shading afford, 0.01 to 10000 (docs/decoupled-shading.md)");
  budget->excludes("--shade-rate");
  command.add_option("--time", args.time,
                     "seconds into the scene's glTF animations at the last frame (clamped to each one's keys)")
      ->capture_default_str();
  command.add_option("--fps", args.fps, "glTF animation frames per second, 0.001 to 1000")->capture_default_str();
  command.add_option("--animation", args.animation, "which glTF animations play: all, none, an index or a name")
      ->capture_default_str();
  command.add_flag("--no-aliasing", args.noAliasing, "give every transient its own memory");
  command.add_option("--mark", args.mark,
                     "where shadel-mark finds what composite reads (bilinear with shadel masks): depth-pass (the depth "
                     "pre-pass writes each pixel's request) or raster (it draws the decoupled objects once more)")
      ->check(CLI::IsMember({"depth-pass", "raster"}))
      ->capture_default_str();
  command.add_option("--z-prepass", args.zPrepass,
                     "depth pre-pass of frames without decoupled objects: auto (where overdraw pays for it), on, off")
      ->check(CLI::IsMember({"auto", "on", "off"}))
      ->capture_default_str();
  addMaterialOptions(command, args.materials);
  addFrameOptions(command, args.frameGraph);
}

void addRenderOptions(CLI::App& command, RenderArgs& args) {
  addFrameSetupOptions(command, args);
  command.add_option("-o,--output", args.output, "PNG to write")->capture_default_str();
  command.add_option("--stats", args.stats, "write frame statistics as JSON");
  command.add_option("--trace", args.trace, "write per-pass timings as a Chrome trace (Perfetto)");
  command.add_option("--frames", args.frames,
                     "frames to render, ending at --frame (default 0) and --time: moving objects advance 1/30 s a "
                     "frame and glTF animations 1/--fps s, the camera stays; the last is reported")
      ->capture_default_str();
  command.add_flag("--still", args.still, "moving objects and animations stay at the last frame's pose in all --frames");
  command.add_option("--soak-report", args.soakReport,
                  "write CSV rows (frame, rss_mib, frame_ms, gpu_ms: resident memory, and median frame times since the "
                  "last row) every --soak-every frames, and print RSS and frame time after warm-up (the first tenth "
                  "of --frames) against the end");
  command.add_option("--soak-every", args.soakEvery, "frames per --soak-report row")->capture_default_str();
}

void addViewOptions(CLI::App& command, ViewArgs& args) {
  args.frame.size = "960x540";
  addFrameSetupOptions(command, args.frame);
  command.add_option("--script", args.script,
                     "replay input events from a file, one a line (docs/viewer.md): key, mouse move|drag|click, "
                     "scroll, wait, screenshot, resize, quit");
  command.add_option("--record", args.record, "write every frame shown as DIR/frame-NNNNNN.png");
  command.add_option("--screenshot-dir", args.screenshotDir, "where P and the save buttons write")
      ->capture_default_str();
  command.add_flag("--hide-panels", args.hidePanels, "start with the panels hidden (H toggles them)");
}

void checkViewArgs(const ViewArgs& args) { checkRenderArgs(args.frame); }

void checkRenderArgs(const RenderArgs& args) {
  uint32_t width = 0, height = 0;
  parseSize("--size", args.size, width, height);
  constexpr int kIntMax = std::numeric_limits<int>::max();
  if (args.camera) requireInRange("--camera", *args.camera, 0, kIntMax);
  if (args.frame) requireInRange("--frame", *args.frame, 0, kIntMax);
  requireInRange("--path", args.path, 0, kIntMax);
  requireInRange("--frames", args.frames, 1, kMaxFrames);
  requireFiniteInRange("--time", args.time, -kMaxSeconds, kMaxSeconds);
  requireFiniteInRange("--fps", args.fps, 0.001, 1000.0);
  requireInRange("--soak-every", args.soakEvery, 1, kIntMax);
  requireInRange("--shade-rate", args.shadeRate, 1, kMaxShadeRate);
  requireInRange("--frames-in-flight", args.framesInFlight, 1, 2);
  if (args.shadeBudget) requireFiniteInRange("--shade-budget", *args.shadeBudget, 0.01, 10000.0);
  requireFiniteInRange("--storage", args.storage, kMinStorage, kMaxStorage);
  if (args.bias) requireFiniteInRange("--bias", *args.bias, -kMaxAbsBias, kMaxAbsBias);
}

void addGraphOptions(CLI::App& command, GraphArgs& args) {
  addSceneOptions(command, args.scene, args.size, args.mode);
  auto* dot = command.add_flag("--dot", args.dot, "Graphviz DOT");
  command.add_flag("--json", args.json, "JSON")->excludes(dot);
  command.add_flag("--no-aliasing", args.noAliasing, "give every transient its own memory");
  command.add_option("--pick", args.pick, "X,Y: the frame with a pick pending at that pixel (the viewer's click)")
      ->expected(2)
      ->delimiter(',');
  addMaterialOptions(command, args.materials);
  addFrameOptions(command, args.frame);
}

void checkGraphArgs(const GraphArgs& args) {
  uint32_t width = 0, height = 0;
  parseSize("--size", args.size, width, height);
  if (!args.pick.empty()) {
    requireInRange("--pick x", args.pick[0], 0, width - 1);
    requireInRange("--pick y", args.pick[1], 0, height - 1);
  }
}

CLI::App* addBenchOptions(CLI::App& command, BenchArgs& args, GraphBenchArgs& graphArgs) {
  command.add_option("scenes", args.scenes, "scenes (default: the built-in scene)");
  command.add_option("--out", args.out, "output directory")->capture_default_str();
  command.add_option("--sizes", args.sizes, "output sizes, e.g. 640x360 1280x720 (each side 1 to " + std::to_string(kMaxOutputSide) + ")")->capture_default_str();
  command.add_option("--repetitions", args.repetitions, "timed frames per configuration, 1 or more")->capture_default_str();
  command.add_option("--flicker-frames", args.flickerFrames, "frames along the sub-pixel camera path, 2 or more")->capture_default_str();
  command.add_option("--reference-scale", args.referenceScale, "reference samples per pixel side, 1 to 8")->capture_default_str();
  command.add_flag("--baseline", args.baseline,
                   "each decoupled filter also with shadel-mark as before issue 14 (the trilinear footprint whatever "
                   "the filter, a remap read per tap), alternated in the same run");
  command.add_flag("--filters-only", args.filtersOnly, "forward and the three filters only (no bias sweep)");
  command.add_flag("--scene-ratios", args.sceneRatios,
                   "instead of the configuration sweep: every scene after the first against the first (seen from "
                   "the first scene's first camera path, if it has one), forward and decoupled, each also as before issue 14 (without "
                   "occlusion culling), alternated; "
                   "writes scene-ratios.json");
  command.add_flag("--without-occluded-skip", args.withoutOccludedSkip,
                   "--scene-ratios: also decoupled without the occluded-entry skip (every entry of objects the "
                   "occlusion cull hides is visited, as before), alternated; skip_ratio: with ÷ without");
  command.add_flag("--effects", args.effects,
                   "instead of the configuration sweep: what each effect costs, forward and decoupled, alternated "
                   "(shadows per light by type, light culling against brute force by light count, environment light "
                   "and its one-time prefilter, bloom) and the ꟻLIP the effect adds; writes effects.json");
  command.add_option("--effect-groups", args.effectGroups, "--effects: which comparisons (comma-separated: shadows, lights, ibl, bloom)")
      ->delimiter(',')
      ->capture_default_str();
  command.add_option("--light-counts", args.lightCounts,
                     "--effects: point-light counts of the culling comparison (comma-separated, each 1 to 4096)")
      ->delimiter(',')
      ->capture_default_str();
  command.add_option("--play", args.play,
                     "instead of the configuration sweep: forward and decoupled while the scenes' glTF animations "
                     "play, this many frames 1/30 s apart, alternated frame by frame; median GPU frame times, their "
                     "ratio, shadels per covered pixel and composite misses; writes playback.json");
  auto* shimmer = command.add_flag("--shimmer", args.shimmer, "add the shimmer case (default scene's gold sphere, close up)");
  command.add_option("--materials", args.materials,
                  "instead of the configuration sweep: for each of these materials (comma-separated, e.g. "
                  "gltf-pbr,bumps,skin,marble) forward and decoupled trilinear with the adjuster, against a forward "
                  "reference of the same material; writes materials.json and materials.csv (--flicker-frames and "
                  "--shimmer do not apply)")
      ->delimiter(',')
      ->excludes(shimmer);
  command.add_option("--shade-rates", args.shadeRates,
                     "instead of the configuration sweep: forward and decoupled at each of these shade rates "
                     "(comma-separated, each 1 or more, e.g. 1,2,4), alternated frame by frame along a moving camera "
                     "path; median raster-frame times and their ratio to forward; writes shade-rate.json")
      ->delimiter(',');
  command.add_option("--path-frames", args.pathFrames, "--shade-rates: raster frames along the path, 2 or more")
      ->capture_default_str();
  command.add_option("--move-object", args.moveObject,
                     "--shade-rates: this object (by name, e.g. 'gold sphere') also moves, on a circle of 0.25 units "
                     "every 96 frames (it is reshaded every frame)");
  command.add_option("--shade-budgets", args.shadeBudgets,
                     "--shade-rates: also budget mode with each of these layer-shade budgets in ms (comma-separated)")
      ->delimiter(',');
  command.add_option("--rate-material", args.rateMaterial, "--shade-rates: every object's material, e.g. split-pbr");
  command.add_flag("--unkept-layers", args.unkeptLayers,
                   "--shade-rates: each rate also with view-independent layers computed whenever their chunk is");
  command.add_option("--frames-in-flight", args.framesInFlight,
                     "--shade-rates: 2 also runs each rate above 1 with two frames in flight (the shade frame as the "
                     "raster frame's tail), and times consecutive frames of each, with and without (1 or 2)")
      ->capture_default_str();
  auto* graph = command.add_subcommand("graph",
                                       "Instead: declare + compile time of synthetic render graphs by size (no device); "
                                       "writes graph.json and graph.csv into --out");
  graph->add_option("--passes", graphArgs.passes, "graph sizes in passes, e.g. 10,100,1000")
      ->delimiter(',')
      ->capture_default_str();
  graph->add_option("--graphs", graphArgs.graphs, "distinct graphs per size")->capture_default_str();
  graph->add_option("--repetitions", graphArgs.repetitions, "timed rounds")->capture_default_str();
  graph->fallthrough();  // --out belongs to bench
  return graph;
}

void checkBenchArgs(const BenchArgs& args) {
  requireInRange("--repetitions", args.repetitions, 1, 100000);
  requireInRange("--flicker-frames", args.flickerFrames, 2, 10000);  // flicker is the change between frames
  requireInRange("--reference-scale", args.referenceScale, 1, 8);
  for (const int rate : args.shadeRates) requireInRange("--shade-rates", rate, 1, kMaxShadeRate);
  for (const double ms : args.shadeBudgets) requireFiniteInRange("--shade-budgets", ms, 0.01, 10000.0);
  requireInRange("--path-frames", args.pathFrames, 2, 100000);
  requireInRange("--frames-in-flight", args.framesInFlight, 1, 2);
  requireInRange("--play", args.play, 0, 100000);
  if (args.sizes.empty()) throw std::invalid_argument("--sizes: expected at least one WIDTHxHEIGHT");
  if (args.sceneRatios && args.scenes.size() < 2)
    throw std::invalid_argument("--scene-ratios: expected at least two scenes (the first is the baseline)");
  if (args.effectGroups.empty()) throw std::invalid_argument("--effect-groups: expected at least one of shadows, lights, ibl, bloom");
  for (const auto& group : args.effectGroups)
    if (group != "shadows" && group != "lights" && group != "ibl" && group != "bloom")
      throw std::invalid_argument("--effect-groups: unknown '" + group + "' (expected shadows, lights, ibl or bloom)");
  if (args.lightCounts.empty()) throw std::invalid_argument("--light-counts: expected at least one count");
  for (const int count : args.lightCounts) requireInRange("--light-counts", count, 1, 4096);  // the frame's light buffer
  for (const auto& size : args.sizes) {
    uint32_t w = 0, h = 0;
    parseSize("--sizes", size, w, h);
    if (uint64_t(std::max(w, h)) * uint32_t(args.referenceScale) > kMaxOutputSide)
      throw std::invalid_argument("--reference-scale " + std::to_string(args.referenceScale) + ": the reference of " +
                                  size + " would exceed " + std::to_string(kMaxOutputSide) + " pixels a side");
  }
}

CLI::App* addBenchTargetsOptions(CLI::App& bench, TargetsBenchArgs& args) {
  auto* targets = bench.add_subcommand(
      "targets",
      "Instead: issue 14's targets, every row measured in one run (configurations alternated, medians), each "
      "figure against its target; writes targets.json and targets.md into --out");
  targets->add_option("--sizes", args.sizes,
                      "output sizes of every row, e.g. 160x90 (default: 1280x720; shadels per pixel and PSNR also "
                      "640x360)");
  targets->add_option("--scenes", args.scenes,
                      "measure only these scenes (comma-separated): default, a sample model's name (e.g. "
                      "DamagedHelmet), cull (the hidden and off-screen objects scenes); the rest are reported as "
                      "not measured")
      ->delimiter(',');
  targets->add_option("--repetitions", args.repetitions, "timed rounds, 1 or more")->capture_default_str();
  targets->add_option("--assets", args.assets, "the glTF sample models' directory (<dir>/<model>/glTF/<model>.gltf)")
      ->capture_default_str();
  targets->add_option("--scene-files", args.sceneFiles, "the directory of cull-base.json, cull-hidden.json and cull-offscreen.json")
      ->capture_default_str();
  targets->add_option("--baseline-json", args.baselineJson,
                      "an earlier targets.json (e.g. docs/results/targets-before-issue-14.json): every figure's "
                      "before, and the rows whose target is relative to it");
  targets->fallthrough();  // --out belongs to bench
  return targets;
}

void checkBenchTargetsArgs(const TargetsBenchArgs& args) {
  requireInRange("--repetitions", args.repetitions, 1, 100000);
  for (const auto& size : args.sizes) {
    uint32_t w = 0, h = 0;
    parseSize("--sizes", size, w, h);
  }
  for (const auto& scene : args.scenes)
    if (scene.empty()) throw std::invalid_argument("--scenes: expected scene names, got an empty one");
}

}  // namespace sg::app
