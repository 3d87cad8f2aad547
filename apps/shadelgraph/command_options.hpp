#pragma once
// The options of the device commands (render, graph, bench) and their checks,
// apart from the code that runs them: nothing here touches Vulkan, so the CLI
// fuzz target (tests/fuzz/fuzz_cli.cpp) parses and checks exactly what the
// app does without a device.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench_graph.hpp"

namespace sg::app {

// --plugin FILE, --plugin-dir DIR (both repeatable) and --material NAME of the device commands.
struct MaterialArgs {
  std::vector<std::string> libraries, directories;
  std::string material;  // every object's material; empty: the scene's
  // What AppSession loads: the directories' plugins, then the named libraries.
  std::vector<std::string> paths() const;
};
void addMaterialOptions(CLI::App& command, MaterialArgs& args);

// --frame-graph FILE|NAME and --object-mode NAME=MODE (repeatable).
struct FrameArgs {
  std::string frameGraph;  // a built-in or plugin frame's name, or a JSON file; empty: "decoupled"
  std::vector<std::string> objectModes;  // "object=forward|decoupled|auto"
};
void addFrameOptions(CLI::App& command, FrameArgs& args);

struct RenderArgs {
  std::string scene;
  std::string output = "out/render.png";
  std::string size = "1280x720";
  std::optional<int> camera;  // empty: the scene's first, else framing
  std::optional<int> frame;   // a camera-path frame instead of a camera
  int path = 0;
  std::string mode;  // empty: each object's own mode (glTF extras, scene file; default auto)
  std::string view = "final";
  int filter = 1;  // bilinear: the most accurate decoupled filter (docs/decoupled-shading.md)
  std::optional<double> bias;  // empty: the adjuster decides
  double storage = 2.0;
  int shadeRate = 1;  // a shade frame every this many raster frames (docs/decoupled-shading.md)
  int framesInFlight = 1;  // 2: the shade frame runs past its raster frame (docs/decoupled-shading.md)
  std::optional<double> shadeBudget;  // budget mode: layer-shade milliseconds a frame (instead of --shade-rate)
  std::string stats;
  std::string trace;
  int frames = 2;
  bool still = false;  // moving objects and animations stay at the last frame's pose in every one of --frames
  double time = 0.0;   // seconds into the scene's glTF animations at the last frame
  double fps = 30.0;   // frames before the last step back 1/fps seconds each (unless --still)
  std::string animation = "all";
  std::string soakReport;
  int soakEvery = 100;
  bool noAliasing = false;
  std::string zPrepass = "auto";  // the forward frame's depth pre-pass: auto, on, off
  std::string mark = "depth-pass";  // shadel-mark's requests from the depth pre-pass, or raster (DecoupledSettings::markRequests)
  MaterialArgs materials;
  FrameArgs frameGraph;
};
// What sets up the frame (scene, size, camera, mode, decoupled settings, materials, frame graph): render's and view's.
void addFrameSetupOptions(CLI::App& command, RenderArgs& args);
void addRenderOptions(CLI::App& command, RenderArgs& args);
// Every option's value, before the scene is loaded or the device started.
void checkRenderArgs(const RenderArgs& args);

struct ViewArgs {
  RenderArgs frame;  // the frame set-up options render has (its output options unused)
  std::string script;  // input events to replay
  std::string record;  // directory: every frame shown as a PNG
  std::string screenshotDir = "out/view";
  bool hidePanels = false;
};
void addViewOptions(CLI::App& command, ViewArgs& args);
void checkViewArgs(const ViewArgs& args);

struct GraphArgs {
  std::string scene;
  std::string size = "1280x720";
  std::string mode;
  bool dot = false, json = false, noAliasing = false;
  std::vector<int> pick;  // x, y: the frame with a pick pending there
  MaterialArgs materials;
  FrameArgs frame;
};
void addGraphOptions(CLI::App& command, GraphArgs& args);
void checkGraphArgs(const GraphArgs& args);

struct BenchArgs {
  std::vector<std::string> scenes;
  std::string out = "out/bench";
  std::vector<std::string> sizes{"640x360"};
  int repetitions = 5;
  int flickerFrames = 12;
  int referenceScale = 4;  // reference: this many samples per pixel side (4 -> 16 spp)
  bool shimmer = false;    // also the shimmer case: the default scene's gold sphere close up
  std::vector<std::string> materials;  // non-empty: the material sweep instead (bench_materials.cpp)
  bool baseline = false;     // each filter also with shadel-mark as before issue 14
  bool filtersOnly = false;  // no bias sweep
  std::vector<int> shadeRates;  // non-empty: the shade-rate sweep instead (bench_shade_rate.cpp)
  int pathFrames = 24;          // the shade-rate sweep: raster frames along its moving camera path
  std::string moveObject;       // the shade-rate sweep: an object (by name) that moves too
  std::vector<double> shadeBudgets;  // the shade-rate sweep: budget mode configurations
  std::string rateMaterial;     // the shade-rate sweep: every object's material
  bool unkeptLayers = false;    // the shade-rate sweep: each rate also without keeping view-independent layers
  int framesInFlight = 1;       // the shade-rate sweep: 2 adds each rate above 1 with two frames in flight
  bool withoutOccludedSkip = false;  // --scene-ratios: also decoupled without the occluded-entry skip
  bool sceneRatios = false;  // each scene against the first instead (bench_scenes.cpp)
  bool effects = false;      // what each effect costs and adds instead (bench_effects.cpp)
  int play = 0;              // > 0: this many frames of the scenes' animations, forward and decoupled, instead (bench_playback.cpp)
  std::vector<std::string> effectGroups{"shadows", "lights", "ibl", "bloom"};  // --effects: which comparisons
  std::vector<int> lightCounts{8, 16, 32, 64, 128, 300};  // --effects: point lights (1000: brute force ~2 min a frame here)
};
// bench's options, and its subcommand "graph" (returned) with graphArgs'.
CLI::App* addBenchOptions(CLI::App& command, BenchArgs& args, GraphBenchArgs& graphArgs);
// Every option's value, before the device starts: no empty sweep, no reference beyond the size limit.
void checkBenchArgs(const BenchArgs& args);

// bench targets: issue 14's table of targets measured in one run (bench_targets.cpp).
struct TargetsBenchArgs {
  std::vector<std::string> sizes;   // empty: each row's own (1280x720; shadels per pixel and PSNR also 640x360)
  std::vector<std::string> scenes;  // empty: every row's scenes; else only these (default, a sample model, cull)
  int repetitions = 5;              // timed rounds
  std::string assets = "../shared/assets/gltf";  // the sample models, one directory each
  std::string sceneFiles = "benchmarks/scenes";  // cull-base.json, cull-hidden.json, cull-offscreen.json
  std::string baselineJson;  // an earlier targets.json: each figure's "before"
};
// bench's subcommand "targets" (returned); --out stays bench's.
CLI::App* addBenchTargetsOptions(CLI::App& bench, TargetsBenchArgs& args);
void checkBenchTargetsArgs(const TargetsBenchArgs& args);

}  // namespace sg::app
