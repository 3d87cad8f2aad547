// The shadelgraph CLI as a user runs it: exit codes, messages, the PNG it
// writes and the plan it prints. Runs with SG_VALIDATION=1 (set by ctest for
// device tests), so any validation message makes the command fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadelgraph/image/png.hpp>

#include "cli_run.hpp"
#include "test_support.hpp"

namespace {

using Run = sg::test::CliRun;

Run run(const std::string& args, const std::string& stderrTo = "&1", const std::string& redirect = "") {
  return sg::test::runCli(args, stderrTo, redirect);
}

// One directory per test process (ctest runs each test alone), removed at
// exit: suites running side by side never share files.
std::filesystem::path tempDir() {
  static const sg::test::TempDir dir;
  return dir.path();
}

TEST(Cli, VersionAndHelp) {
  auto version = run("--version");
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_NE(version.output.find("0."), std::string::npos);
  auto help = run("--help");
  EXPECT_EQ(help.exitCode, 0);
  for (const char* command : {"render", "graph", "inspect"}) EXPECT_NE(help.output.find(command), std::string::npos) << command;
}

TEST(Cli, RenderWritesANonBlankPngAndATimingTable) {
  const auto png = tempDir() / "default.png";
  std::filesystem::remove(png);
  auto r = run("render -o " + png.string() + " --size 160x90 --frames 1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // The default scene is decoupled: no object is shaded forward, so no forward-opaque.
  for (const char* pass : {"z-prepass", "composite", "exposure", "tonemap", "GPU ms"})
    EXPECT_NE(r.output.find(pass), std::string::npos) << pass << " missing from:\n" << r.output;
  const auto image = sg::image::readPng(png);
  ASSERT_EQ(image.width, 160u);
  ASSERT_EQ(image.height, 90u);
  // Not blank: many distinct colours.
  std::set<uint32_t> colours;
  for (size_t i = 0; i < image.pixels.size(); i += 4)
    colours.insert(uint32_t(image.pixels[i]) << 16 | uint32_t(image.pixels[i + 1]) << 8 | image.pixels[i + 2]);
  EXPECT_GT(colours.size(), 500u);
}

TEST(Cli, BadArgumentsFailWithOneLineReason) {
  auto size = run("render --size 12by7");
  EXPECT_NE(size.exitCode, 0);
  EXPECT_NE(size.output.find("--size"), std::string::npos) << size.output;
  auto missing = run("render /nonexistent/scene.gltf");
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.output.find("/nonexistent/scene.gltf"), std::string::npos) << missing.output;
  auto mode = run("render --mode sideways --size 32x32");
  EXPECT_NE(mode.exitCode, 0);
  EXPECT_NE(mode.output.find("--mode"), std::string::npos) << mode.output;
}

TEST(Cli, GraphJsonListsPassesResourcesBarriersAndWaits) {
  auto r = run("graph --json --size 160x90");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto plan = nlohmann::json::parse(r.output);
  ASSERT_TRUE(plan.contains("passes"));
  ASSERT_TRUE(plan.contains("resources"));
  std::set<std::string> names;
  for (const auto& p : plan["passes"]) {
    names.insert(p["name"].get<std::string>());
    EXPECT_TRUE(p.contains("queue"));
    EXPECT_TRUE(p["culled"].is_boolean());
    EXPECT_TRUE(p["accesses"].is_array());
    EXPECT_TRUE(p["barriers"].is_array());
    EXPECT_TRUE(p["waits"].is_array());
  }
  EXPECT_TRUE(names.count("composite"));  // the default scene is decoupled
  // The default scene has no masked or blended material: no pass for them.
  EXPECT_FALSE(names.count("alpha-blend"));
  EXPECT_FALSE(names.count("alpha-mask"));
  bool transientWithMemory = false;
  for (const auto& res : plan["resources"]) {
    EXPECT_TRUE(res.contains("kind"));
    if (res["kind"] == "TransientImage") transientWithMemory |= res.contains("memory") && res["memory"].contains("offset");
  }
  EXPECT_TRUE(transientWithMemory);
}

std::string asset(const std::string& model) { return sg::test::samplePath(model).string(); }

TEST(Cli, OnlyScenesWithMaskedOrBlendedMaterialsGetThosePasses) {
  SG_REQUIRE_ASSETS();
  const auto passes = [](const std::string& mode) {
    auto r = run("graph --json --size 64x64 --mode " + mode + " " + asset("AlphaBlendModeTest"));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::set<std::string> names;
    if (r.exitCode != 0) return names;
    const auto plan = nlohmann::json::parse(r.output);  // named: a temporary's member would dangle in the loop
    for (const auto& p : plan["passes"]) names.insert(p["name"].get<std::string>());
    return names;
  };
  const auto forward = passes("forward");
  EXPECT_TRUE(forward.count("alpha-blend"));
  EXPECT_TRUE(forward.count("alpha-mask"));
  // Decoupled, the masked quads are alpha-tested by shadel-mark and composite:
  // no forward alpha-mask pass; the blended ones stay forward.
  const auto decoupled = passes("decoupled");
  EXPECT_TRUE(decoupled.count("alpha-blend"));
  EXPECT_FALSE(decoupled.count("alpha-mask"));
  EXPECT_TRUE(decoupled.count("composite"));
}

TEST(Cli, InspectReportsChartVerdicts) {
  SG_REQUIRE_ASSETS();
  auto suzanne = run("inspect " + asset("Suzanne"));
  ASSERT_EQ(suzanne.exitCode, 0) << suzanne.output;
  EXPECT_NE(suzanne.output.find("chart: unique"), std::string::npos) << suzanne.output;
  // Unique, but its radial UVs starve half the head of shadels: not used as is.
  EXPECT_NE(suzanne.output.find("coarser per side than the mean (uneven"), std::string::npos) << suzanne.output;
  auto helmet = run("inspect " + asset("DamagedHelmet"));
  ASSERT_EQ(helmet.exitCode, 0) << helmet.output;
  EXPECT_NE(helmet.output.find("15452 triangles"), std::string::npos) << helmet.output;
  EXPECT_NE(helmet.output.find("chart: not unique"), std::string::npos) << helmet.output;
  EXPECT_NE(helmet.output.find("10 zero-UV-area triangles"), std::string::npos) << helmet.output;
  auto box = run("inspect " + asset("Box"));
  EXPECT_NE(box.output.find("UV sets: none"), std::string::npos) << box.output;
}

// inspect lists every object with what render would choose for it at load, and why.
TEST(Cli, InspectListsEachObjectsShadingAndWhy) {
  SG_REQUIRE_ASSETS();
  const auto lines = [](const std::string& text, const std::string& part) {
    size_t n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
  };
  auto decoupled = run("inspect --mode decoupled " + asset("AlphaBlendModeTest"));
  ASSERT_EQ(decoupled.exitCode, 0) << decoupled.output;
  const size_t instances = std::stoul(decoupled.output.substr(decoupled.output.find("meshes, ") + 8));
  EXPECT_EQ(lines(decoupled.output, "\nobject '"), instances) << decoupled.output;
  EXPECT_EQ(lines(decoupled.output, "': forward (alpha-blended material"), 2u) << decoupled.output;
  EXPECT_EQ(lines(decoupled.output, "': decoupled ("), instances - 2) << "opaque and alpha-mask objects: " << decoupled.output;
  auto forward = run("inspect --mode forward " + asset("AlphaBlendModeTest"));
  ASSERT_EQ(forward.exitCode, 0) << forward.output;
  EXPECT_EQ(lines(forward.output, "': decoupled ("), 0u) << forward.output;
  EXPECT_EQ(lines(forward.output, "': forward ("), instances) << forward.output;
  // render --stats lists the same objects in the same words.
  const auto stats = tempDir() / "alpha-blend-stats.json";
  auto rendered = run("render --mode decoupled --size 64x36 --frames 1 -o " + (tempDir() / "alpha-blend.png").string() +
                      " --stats " + stats.string() + " " + asset("AlphaBlendModeTest"));
  ASSERT_EQ(rendered.exitCode, 0) << rendered.output;
  std::ifstream in(stats);
  const auto objects = nlohmann::json::parse(in)["objects"];
  ASSERT_EQ(objects.size(), instances);
  for (const auto& object : objects) {
    const std::string line = "object '" + object["name"].get<std::string>() + "': " + object["shading"].get<std::string>() +
                             " (" + object["reason"].get<std::string>() + ")\n";
    EXPECT_NE(decoupled.output.find(line), std::string::npos) << line << " not in inspect's:\n" << decoupled.output;
  }
}

// Two quads, each a mesh of its own whose texture (16² scaled 256 times by
// KHR_texture_transform) asks for a 4096² level 0: two such triangle-ID maps
// (85 MiB each with their levels) are more than lavapipe's 128 MiB storage
// buffer, so one is shrunk to 2048², and render says so in one line.
TEST(Cli, RenderWarnsOfAShrunkTriangleIdMap) {
  const auto dir = tempDir() / "shrunk";
  std::filesystem::create_directories(dir);
  const float vertices[] = {0, 0, 0, 0, 1,  1, 0, 0, 1, 1,  1, 1, 0, 1, 0,  0, 1, 0, 0, 0};  // position, uv
  const uint16_t indices[] = {0, 1, 2, 0, 2, 3};
  std::vector<char> bytes(sizeof vertices + sizeof indices);
  std::memcpy(bytes.data(), vertices, sizeof vertices);
  std::memcpy(bytes.data() + sizeof vertices, indices, sizeof indices);
  std::ofstream(dir / "quad.bin", std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  const std::vector<uint8_t> texels(16 * 16 * 4, 200);
  sg::image::writePng(dir / "grey.png", 16, 16, texels.data());
  const auto gltf = nlohmann::json::parse(R"({
    "asset": {"version": "2.0"}, "extensionsUsed": ["KHR_texture_transform"], "scene": 0,
    "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"name": "left quad", "mesh": 0, "translation": [-1.1, 0, 0]},
              {"name": "right quad", "mesh": 1, "translation": [0.1, 0, 0]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]},
               {"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0,
                   "extensions": {"KHR_texture_transform": {"scale": [256, 256]}}}}}],
    "textures": [{"source": 0}], "images": [{"uri": "grey.png"}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 4, "type": "VEC2"},
                  {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    "bufferViews": [{"buffer": 0, "byteLength": 80, "byteStride": 20}, {"buffer": 0, "byteOffset": 80, "byteLength": 12}],
    "buffers": [{"uri": "quad.bin", "byteLength": 92}]})");
  std::ofstream(dir / "quads.gltf") << gltf.dump();
  const auto r = run("render --mode decoupled --size 64x36 --frames 1 -o " + (dir / "quads.png").string() + " " +
                     (dir / "quads.gltf").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  size_t warnings = 0;
  for (size_t at = r.output.find("warning: "); at != std::string::npos; at = r.output.find("warning: ", at + 1)) ++warnings;
  EXPECT_EQ(warnings, 1u) << r.output;
  EXPECT_NE(r.output.find("warning: object 'left quad' primitive 0: triangle-ID map shrunk to fit the 128 MiB buffer, "
                          "level 0 4096 -> 2048\n"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("2 objects decoupled, 0 forward"), std::string::npos) << "shrunk, not forward: " << r.output;
}

TEST(Cli, MalformedGltfFailsWithTheFileAndTheProblem) {
  const std::string dir = "/usr/share/assimp/models/glTF2/";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "assimp-testmodels not installed (./sg installs it)";
  auto r = run("render --size 32x32 " + dir + "IndexOutOfRange/IndexOutOfRange.gltf");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("IndexOutOfRange.gltf"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("out of range"), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line: " << r.output;
}

TEST(Cli, MissingTextureIsAnErrorNotABlankMaterial) {
  SG_REQUIRE_ASSETS();
  const auto dir = tempDir() / "missing-texture";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto source = sg::test::assetsDir() / "BoxTextured/glTF";
  for (const char* f : {"BoxTextured.gltf", "BoxTextured0.bin"}) std::filesystem::copy(source / f, dir / f);
  auto r = run("render --size 32x32 " + (dir / "BoxTextured.gltf").string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("CesiumLogoFlat.png"), std::string::npos) << r.output;
}

TEST(Cli, DecoupledStatsHaveTheDocumentedKeys) {
  const auto stats = tempDir() / "stats.json";
  auto r = run("render --mode decoupled --size 96x64 --frames 2 -o " + (tempDir() / "d.png").string() + " --stats " +
               stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(stats);
  const auto json = nlohmann::json::parse(in);
  for (const char* key : {"frame_ms", "pass_ms", "covered_pixels", "shadels_marked", "shadels_allocated",
                          "shadels_shaded", "shadels_per_pixel", "overflow_chunks", "composite_misses", "global_bias",
                          "shade_storage_bytes", "remap_bytes", "objects_decoupled", "objects_forward"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["objects_decoupled"], 11);
  EXPECT_GT(json["covered_pixels"].get<uint64_t>(), 0u);
  EXPECT_EQ(json["composite_misses"], 0);
  // shadel-mark-requests: the default bilinear filter's mark, from requests the z-prepass wrote.
  for (const char* pass : {"shadel-clear", "shadel-mark-requests", "shadel-allocate", "work-aggregate", "layer-shade",
                           "composite"})
    EXPECT_TRUE(json["pass_ms"].contains(pass)) << pass;
  EXPECT_FALSE(json["pass_ms"].contains("shadel-mark"));
  // --mark raster: shadel-mark draws the objects again, and the z-prepass writes no requests.
  r = run("render --mode decoupled --mark raster --size 96x64 --frames 2 -o " + (tempDir() / "d.png").string() +
          " --stats " + stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream raster(stats);
  const auto rasterJson = nlohmann::json::parse(raster);
  EXPECT_TRUE(rasterJson["pass_ms"].contains("shadel-mark"));
  EXPECT_FALSE(rasterJson["pass_ms"].contains("shadel-mark-requests"));
  EXPECT_EQ(rasterJson["composite_misses"], 0);
}

TEST(Cli, AFrameThatDeclaresLastFramesGraphReusesItsPlan) {
  // The first frame compiles; a still scene's later frames declare the same
  // graph, and the executor's compilers hand back the plan (plan_reused).
  const auto stats = tempDir() / "reuse.json";
  for (const char* mode : {"forward", "decoupled"}) {
    for (const int frames : {1, 3}) {
      auto r = run(std::string("render --mode ") + mode + " --size 96x64 --frames " + std::to_string(frames) +
                   " -o /dev/null --stats " + stats.string());
      ASSERT_EQ(r.exitCode, 0) << r.output;
      std::ifstream in(stats);
      const auto json = nlohmann::json::parse(in);
      EXPECT_EQ(json["plan_reused"].get<bool>(), frames > 1) << mode << ", " << frames << " frames";
      EXPECT_EQ(json["composite_misses"], 0) << mode;
    }
  }
}

std::set<std::string> passNames(const std::string& args) {
  auto r = run("graph --json --size 64x64 " + args);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::set<std::string> names;
  const auto plan = nlohmann::json::parse(r.output);
  for (const auto& p : plan["passes"]) names.insert(p["name"].get<std::string>());
  return names;
}

TEST(Cli, OnlyTheShadingTheSceneUsesIsInTheGraph) {
  const auto automatic = passNames("");
  for (const char* pass : {"shadel-clear", "shadel-mark-requests", "shadel-allocate", "work-aggregate", "layer-shade",
                           "composite"})
    EXPECT_TRUE(automatic.count(pass)) << pass << ": the default scene is decoupled under auto";
  const auto forward = passNames("--mode forward");
  for (const auto& name : forward) EXPECT_EQ(name.find("shadel-"), std::string::npos) << name;
  EXPECT_FALSE(forward.count("composite"));
  EXPECT_TRUE(forward.count("forward-opaque"));
}

TEST(Cli, DecoupledAndForwardObjectsInOneFrame) {
  SG_REQUIRE_ASSETS();
  const auto stats = tempDir() / "mixed.json";
  auto r = run("render " + std::string(SG_SOURCE_DIR) + "/tests/scenes/mixed.json --frame 10 --size 160x90 -o " +
               (tempDir() / "mixed.png").string() + " --stats " + stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(stats);
  const auto json = nlohmann::json::parse(in);
  EXPECT_EQ(json["objects_decoupled"], 1);  // the helmet, with an automatic chart
  EXPECT_GT(json["objects_forward"].get<int>(), 1);  // the box (by request) and the engine's 67 parts
  EXPECT_EQ(json["composite_misses"], 0);
  EXPECT_GT(json["covered_pixels"].get<int>(), 0);
}

TEST(Cli, DebugViewsRender) {
  for (const char* view : {"level", "occupancy", "sheet"}) {
    const auto png = tempDir() / (std::string("view-") + view + ".png");
    auto r = run(std::string("render --size 96x64 --frames 1 --view ") + view + " -o " + png.string());
    ASSERT_EQ(r.exitCode, 0) << view << ": " << r.output;
    const auto image = sg::image::readPng(png);
    std::set<uint32_t> colours;
    for (size_t i = 0; i < image.pixels.size(); i += 4)
      colours.insert(uint32_t(image.pixels[i]) << 16 | uint32_t(image.pixels[i + 1]) << 8 | image.pixels[i + 2]);
    EXPECT_GT(colours.size(), 3u) << view;
  }
}

// The benchmark's output format on a tiny run (figures are not asserted: benchmarks, not timed tests).
TEST(Cli, BenchWritesResultsForEveryConfiguration) {
  const auto dir = tempDir() / "bench";
  std::filesystem::remove_all(dir);
  auto r = run("bench --out " + dir.string() + " --sizes 64x36 --repetitions 1 --flicker-frames 2 --reference-scale 2");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(dir / "results.json");
  const auto json = nlohmann::json::parse(in);
  for (const char* key : {"cpu", "cores", "device", "driver"}) EXPECT_TRUE(json["machine"].contains(key)) << key;
  const auto& configs = json["runs"][0]["configs"];
  EXPECT_GE(configs.size(), 10u);
  std::set<std::string> names;
  for (const auto& c : configs) {
    names.insert(c["config"].get<std::string>());
    for (const char* key : {"frame_ms_median", "pass_ms_median", "shadels_per_pixel", "shade_memory_bytes", "flip_mean",
                            "psnr", "flicker_excess", "composite_misses"})
      EXPECT_TRUE(c.contains(key)) << key;
    EXPECT_GE(c["flip_mean"].get<double>(), 0.0);
    EXPECT_LE(c["flip_mean"].get<double>(), 1.0);
    EXPECT_EQ(c["composite_misses"], 0) << c["config"];
  }
  for (const char* name : {"forward", "decoupled point", "decoupled bilinear", "decoupled trilinear", "decoupled bias -1.0",
                           "decoupled bias +2.0"})
    EXPECT_TRUE(names.count(name)) << name;
  EXPECT_TRUE(std::filesystem::exists(dir / "results.csv"));
}

// The shade-rate sweep's output format on a tiny run: forward, each rate, its
// twin in flight and the budget mode, each with time against forward, error
// against the reference of each path frame, flicker, and where the frame goes
// (figures are not asserted: benchmarks, not timed tests).
TEST(Cli, BenchShadeRatesWritesEveryRateWithErrorAndFlicker) {
  const auto dir = tempDir() / "bench-shade-rates";
  std::filesystem::remove_all(dir);
  auto r = run("bench --shade-rates 1,2 --shade-budgets 5 --frames-in-flight 2 --out " + dir.string() +
               " --sizes 64x36 --path-frames 3 --reference-scale 2");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(dir / "shade-rate.json");
  const auto json = nlohmann::json::parse(in);
  ASSERT_EQ(json["runs"].size(), 1u);
  const auto& run0 = json["runs"][0];
  EXPECT_EQ(run0["reference_spp"], 4);
  EXPECT_EQ(run0["frames_in_flight"], 2);
  std::set<std::string> names;
  for (const auto& c : run0["configs"]) {
    const auto name = c["config"].get<std::string>();
    names.insert(name);
    for (const char* key : {"frame_ms_median", "frame_ms_mean", "ratio_to_forward", "ratio_mean_to_forward",
                            "pass_groups_ms_median", "raster_passes_ms_median", "psnr_median", "flicker",
                            "flicker_reference", "flicker_excess", "frame_with_tail_ms_mean"})
      EXPECT_TRUE(c.contains(key)) << name << ": " << key;
    EXPECT_GE(c["flip_mean"].get<double>(), 0.0) << name;
    EXPECT_LE(c["flip_mean"].get<double>(), 1.0) << name;
    EXPECT_EQ(c["flip_samples"].size(), 3u) << name << ": one ꟻLIP per path frame";
    EXPECT_GT(c["flicker_reference"].get<double>(), 0.0) << name << ": the orbit moves the reference";
    EXPECT_EQ(c["composite_misses_max"], 0) << name;
    for (const char* group : {"raster", "shade_space", "shading", "gaps"})
      EXPECT_TRUE(c["pass_groups_ms_median"].contains(group)) << name << ": " << group;
    // Only the configurations in flight run a shade frame as a tail; consecutive
    // frames are timed for forward and every rate above 1, with and without.
    EXPECT_EQ(c["tail_ms_median"].is_null(), !c["in_flight"].get<bool>()) << name;
    EXPECT_EQ(c["consecutive_wall_ms_per_frame"].is_null(),
              !(name == "forward" || name.rfind("decoupled rate 2", 0) == 0)) << name;
  }
  for (const char* name : {"forward", "decoupled rate 1", "decoupled rate 2", "decoupled rate 2 in flight",
                           "decoupled budget 5 ms"})
    EXPECT_TRUE(names.count(name)) << name;
  EXPECT_EQ(names.size(), 5u);
}

// The material sweep's output format on a tiny run: every (material, path)
// configuration with the documented keys; times are not asserted.
// bench graph needs no device: medians per size and mode, ratios, and the
// render graph's targets for the sizes given (not asserted: timing is measured, not tested).
TEST(Cli, BenchGraphWritesMediansAndRatiosPerSize) {
  const auto dir = tempDir() / "bench-graph";
  std::filesystem::remove_all(dir);
  auto r = run("bench graph --passes 10,100 --graphs 2 --repetitions 3 --out " + dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("target: 100 passes"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir / "graph.csv"));
  std::ifstream in(dir / "graph.json");
  const auto json = nlohmann::json::parse(in);
  EXPECT_TRUE(json["machine"].contains("cpu"));
  ASSERT_EQ(json["sizes"].size(), 2u);
  for (const auto& size : json["sizes"]) {
    const auto passes = size["passes"].get<double>();
    EXPECT_GT(size["kept_passes_mean"].get<double>(), 0.0);
    EXPECT_LE(size["kept_passes_mean"].get<double>(), passes);
    EXPECT_EQ(size["samples"], 2 * 3) << "graphs x repetitions";
    for (const char* mode : {"fresh", "reused", "unchanged"}) {
      const auto& m = size[mode];
      EXPECT_GT(m["median_us"].get<double>(), 0.0) << mode;
      EXPECT_LE(m["p10_us"].get<double>(), m["median_us"].get<double>()) << mode;
      EXPECT_GE(m["p90_us"].get<double>(), m["median_us"].get<double>()) << mode;
    }
  }
  ASSERT_EQ(json["ratios"].size(), 1u);
  EXPECT_EQ(json["ratios"][0]["passes"], 100);
  EXPECT_EQ(json["ratios"][0]["over"], 10);
  for (const char* mode : {"fresh", "reused", "unchanged"}) {
    const auto& target = json["targets"]["100_passes_at_most_50_us"][mode];
    EXPECT_EQ(target["value"].get<double>(), json["sizes"][1][mode]["median_us"].get<double>()) << mode;
    EXPECT_EQ(target["met"].get<bool>(), target["value"].get<double>() <= 50.0) << mode;
  }
  EXPECT_FALSE(json["targets"].contains("1000_over_100_at_most_10")) << "no 1000-pass size was run";

  auto tooSmall = run("bench graph --passes 1 --out " + dir.string());
  EXPECT_EQ(tooSmall.exitCode, 1);
  EXPECT_NE(tooSmall.output.find("at least 2 passes"), std::string::npos) << tooSmall.output;
}

// The scene-ratio bench on small hidden-objects scenes (boxes behind a wall), tiny: every
// scene and configuration, ratios to the first scene and to the frame as before.
TEST(Cli, BenchSceneRatiosComparesEveryScene) {
  SG_REQUIRE_ASSETS();
  const auto dir = tempDir() / "bench-scene-ratios";
  std::filesystem::remove_all(dir);
  const std::string scenes = std::string(SG_SOURCE_DIR) + "/tests/scenes/";
  auto r = run("bench " + scenes + "boxes.json " + scenes + "boxes-hidden.json --scene-ratios --out " +
               dir.string() + " --sizes 64x36 --repetitions 1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json")) << "--scene-ratios replaces the configuration sweep";
  std::ifstream in(dir / "scene-ratios.json");
  const auto json = nlohmann::json::parse(in);
  ASSERT_EQ(json["runs"].size(), 1u);
  const auto& configs = json["runs"][0]["configs"];
  ASSERT_EQ(configs.size(), 8u);  // 2 scenes x forward, decoupled, each also as before
  for (size_t i = 0; i < configs.size(); ++i) {
    const auto& c = configs[i];
    EXPECT_EQ(c["scene"], i < 4 ? "boxes" : "boxes-hidden");
    EXPECT_GT(c["frame_ms_median"].get<double>(), 0.0);
    // Culling adds no composite misses (at 64x36, one warm-up frame, decoupled has some either way).
    if (!c["as_before"].get<bool>()) {
      EXPECT_LE(c["composite_misses"].get<uint64_t>(), configs[i + 2]["composite_misses"].get<uint64_t>()) << c["config"];
    }
    if (i < 4) {
      EXPECT_DOUBLE_EQ(c["ratio_to_first"].get<double>(), 1.0);
    }
    if (c["as_before"].get<bool>()) {
      EXPECT_DOUBLE_EQ(c["ratio_to_before"].get<double>(), 1.0);
      EXPECT_FALSE(c["pass_ms_median"].contains("occlusion-cull")) << c["config"];
    } else {
      EXPECT_TRUE(c["pass_ms_median"].contains("occlusion-cull")) << c["config"];
    }
  }
}

// The effects bench, tiny: every comparison in both paths, and what the
// images must show whatever the timing: culling changes nothing (its lists are
// exact supersets), shadows and bloom change the image (figures are not asserted).
TEST(Cli, BenchEffectsComparesEveryEffectInBothPaths) {
  const auto dir = tempDir() / "bench-effects";
  std::filesystem::remove_all(dir);
  auto r = run("bench --effects --out " + dir.string() + " --sizes 64x36 --repetitions 1 --light-counts 4,40");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json")) << "--effects replaces the configuration sweep";
  std::ifstream in(dir / "effects.json");
  const auto json = nlohmann::json::parse(in);
  for (const char* key : {"cpu", "cores", "device", "driver"}) EXPECT_TRUE(json["machine"].contains(key)) << key;
  ASSERT_EQ(json["runs"].size(), 1u);
  const auto& run = json["runs"][0];

  std::set<std::string> shadowGroups;
  for (const auto& g : run["shadows"]) {
    const auto name = g["light_type"].get<std::string>() + " " + g["path"].get<std::string>();
    shadowGroups.insert(name);
    const auto& rows = g["rows"];
    ASSERT_EQ(rows.size(), g["light_type"] == "point" ? 3u : 4u) << name;  // 0, 1, 2 (, 4) shadowed
    EXPECT_EQ(rows[0]["shadowed"], 0) << name;
    EXPECT_DOUBLE_EQ(rows[0]["ratio_to_unshadowed"].get<double>(), 1.0) << name;
    EXPECT_TRUE(rows[0]["ms_per_shadowed_light"].is_null()) << name;
    EXPECT_DOUBLE_EQ(rows.back()["flip_against_all_shadowed"].get<double>(), 0.0) << name;
    EXPECT_GT(g["flip_unshadowed_against_shadowed"].get<double>(), 0.001) << name << ": shadows must show";
    for (const auto& row : rows) EXPECT_GT(row["frame_ms_median"].get<double>(), 0.0) << name;
  }
  EXPECT_EQ(shadowGroups, (std::set<std::string>{"directional forward", "directional decoupled", "spot forward",
                                                  "spot decoupled", "point forward", "point decoupled"}));

  const auto& lights = run["lights"]["rows"];
  ASSERT_EQ(lights.size(), 4u);  // 2 counts x 2 paths
  for (const auto& row : lights) {
    const auto name = row["lights"].dump() + " " + row["path"].get<std::string>();
    EXPECT_LT(row["flip_culled_against_brute_force"].get<double>(), 0.002) << name << ": culling must not change the image";
    EXPECT_GT(row["culled_ms_median"].get<double>(), 0.0) << name;
    EXPECT_GT(row["brute_force_ms_median"].get<double>(), 0.0) << name;
  }
  EXPECT_TRUE(run["lights"]["culling_faster_from"].contains("forward"));
  EXPECT_TRUE(run["lights"]["culling_faster_from"].contains("decoupled"));

  EXPECT_GT(run["ibl"]["prefilter_ms_median"].get<double>(), 0.0) << "the first frame prefilters";
  ASSERT_EQ(run["ibl"]["rows"].size(), 2u);
  for (const auto& row : run["ibl"]["rows"]) EXPECT_GT(row["flip_sky_against_environment"].get<double>(), 0.001);
  ASSERT_EQ(run["bloom"]["rows"].size(), 2u);
  for (const auto& row : run["bloom"]["rows"]) {
    EXPECT_GT(row["bloom_pass_ms_median"].get<double>(), 0.0) << row["path"];
    EXPECT_GT(row["flip_no_bloom_against_bloom"].get<double>(), 0.001) << row["path"];
  }
}

TEST(Cli, BenchMaterialsWritesEveryMaterialAndPath) {
  const auto dir = tempDir() / "bench-materials";
  std::filesystem::remove_all(dir);
  auto r = run("bench --materials gltf-pbr,marble --out " + dir.string() +
               " --sizes 64x36 --repetitions 1 --reference-scale 2");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json")) << "--materials replaces the configuration sweep";
  EXPECT_TRUE(std::filesystem::exists(dir / "materials.csv"));
  std::ifstream in(dir / "materials.json");
  const auto json = nlohmann::json::parse(in);
  for (const char* key : {"cpu", "cores", "device", "driver"}) EXPECT_TRUE(json["machine"].contains(key)) << key;
  ASSERT_EQ(json["runs"].size(), 1u);
  const auto& configs = json["runs"][0]["configs"];
  std::set<std::string> seen;
  for (const auto& c : configs) {
    const auto material = c["material"].get<std::string>(), path = c["path"].get<std::string>();
    seen.insert(material + " " + path);
    for (const char* key : {"material_run", "layers", "frame_ms_median", "gpu_ms_median", "pass_ms_median",
                            "layer_shade_ms_median", "layer_dispatches", "layer_reuse", "history_bytes",
                            "transient_bytes", "shade_memory_bytes", "flip_mean", "psnr", "composite_misses",
                            "persistent"})
      EXPECT_TRUE(c.contains(key)) << material << " " << path << ": " << key;
    EXPECT_GE(c["flip_mean"].get<double>(), 0.0);
    EXPECT_LE(c["flip_mean"].get<double>(), 1.0);
    EXPECT_EQ(c["composite_misses"], 0) << c["config"];
    EXPECT_TRUE(std::filesystem::exists(dir / c["image"].get<std::string>())) << c["image"];
    if (path == "decoupled") {
      EXPECT_TRUE(c["pass_ms_median"].contains("layer-shade")) << material;
      EXPECT_GT(c["layer_dispatches"].get<int>(), 0) << material;
    } else {
      EXPECT_FALSE(c["pass_ms_median"].contains("layer-shade")) << material;
    }
    // Only a decoupled material with a persistent layer has history and the first/cold/steady comparison.
    const bool persistent = material == "marble" && path == "decoupled";
    EXPECT_EQ(c["persistent"].is_null(), !persistent) << material << " " << path;
    EXPECT_EQ(c["history_bytes"].get<uint64_t>() > 0, persistent) << material << " " << path;
    if (persistent) {
      for (const char* phase : {"first_frame", "cold", "steady"})
        EXPECT_TRUE(c["persistent"][phase]["layer_reuse"].contains("marble")) << phase;
      EXPECT_TRUE(c["persistent"]["first_frame"].contains("layer_shade_ms"));
      EXPECT_TRUE(c["persistent"]["cold"].contains("layer_shade_ms_median"));
      EXPECT_TRUE(c["persistent"]["steady"].contains("layer_shade_ms_median"));
      EXPECT_TRUE(c["persistent"].contains("payoff_ms"));
      // Counts, not times: nothing to reuse in the first and cold frames, some in the steady ones (the
      // adjuster may still move the bias in a one-round run).
      EXPECT_EQ(c["persistent"]["first_frame"]["layer_reuse"]["marble"], 0.0);
      EXPECT_EQ(c["persistent"]["cold"]["layer_reuse"]["marble"], 0.0);
      EXPECT_GT(c["persistent"]["steady"]["layer_reuse"]["marble"].get<double>(), 0.0);
    }
  }
  for (const char* material : {"gltf-pbr", "marble"})
    for (const char* path : {"forward", "decoupled"})
      EXPECT_TRUE(seen.count(std::string(material) + " " + path)) << material << " " << path;
  EXPECT_EQ(configs.size(), 4u);
}

// stdout only (plugins report themselves on stderr).
std::string stdoutOf(const std::string& args) { return run(args, "/dev/null").output; }

struct PlanSummary {
  std::set<std::string> kept;  // passes not culled
  int historyResources = 0;
};

PlanSummary planOf(const std::string& args) {
  const auto plan = nlohmann::json::parse(stdoutOf("graph --json --size 160x90 " + args));
  PlanSummary s;
  for (const auto& p : plan["passes"])
    if (!p["culled"].get<bool>()) s.kept.insert(p["name"].get<std::string>());
  for (const auto& r : plan["resources"]) s.historyResources += r["kind"] == "History";
  return s;
}

// Only what the scene calls for: the compiled frame holds the layer passes,
// support-expand and history of the visible objects' materials, no more.
TEST(Cli, GraphHoldsOnlyWhatTheMaterialsCallFor) {
  const auto pbr = planOf("--mode decoupled");
  EXPECT_TRUE(pbr.kept.count("layer-shade"));
  EXPECT_FALSE(pbr.kept.count("layer-shade #2")) << "gltf-pbr is one layer";
  EXPECT_FALSE(pbr.kept.count("support-expand")) << "no neighbourhood layer";
  EXPECT_EQ(pbr.historyResources, 0) << "no persistent layer";

  const auto bumps = planOf("--mode decoupled --material bumps");
  EXPECT_TRUE(bumps.kept.count("support-expand"));
  EXPECT_TRUE(bumps.kept.count("layer-shade #2"));
  EXPECT_FALSE(bumps.kept.count("layer-shade #3"));
  EXPECT_EQ(bumps.historyResources, 1) << "its height layer is kept across frames (a surface layer): last frame's "
                                          "height image (chunks keep their slots: no remap table to keep)";

  const auto skin = planOf("--mode decoupled --material skin");
  EXPECT_TRUE(skin.kept.count("layer-shade #3"));
  EXPECT_FALSE(skin.kept.count("layer-shade #4"));

  const auto marble = planOf("--mode decoupled --material marble");
  EXPECT_FALSE(marble.kept.count("support-expand"));
  EXPECT_EQ(marble.historyResources, 1) << "last frame's marble image (chunks keep their slots)";

  const auto forward = planOf("--mode forward --material skin");
  EXPECT_FALSE(forward.kept.count("layer-shade"));
  EXPECT_FALSE(forward.kept.count("support-expand"));
  EXPECT_EQ(forward.historyResources, 0);
}

TEST(Cli, StatsReportLayerDispatchesAndReuse) {
  const auto stats = tempDir() / "marble-stats.json";
  auto r = run("render --mode decoupled --material marble --frames 3 --size 160x90 -o " +
               (tempDir() / "marble.png").string() + " --stats " + stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(stats);
  const auto s = nlohmann::json::parse(in);
  EXPECT_EQ(s["layer_dispatches"].get<int>(), 2 * s["objects_decoupled"].get<int>());
  EXPECT_EQ(s["layers"], nlohmann::json({"marble", "marble-shade"}));
  ASSERT_TRUE(s["layer_reuse"].contains("marble"));
  EXPECT_GT(s["layer_reuse"]["marble"].get<double>(), 0.9) << "a still camera reuses last frame's marble";
  EXPECT_GT(s["history_bytes"].get<double>(), 0.0);
}

TEST(Cli, UnknownMaterialIsNamedWithTheKnownOnes) {
  auto r = run("graph --material velvet");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.output.find("no material 'velvet'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("gltf-pbr"), std::string::npos) << r.output;
}

TEST(Cli, PluginPassRunsInThePluginsFrameOnly) {
  const auto plan = planOf(std::string("--plugin ") + SG_PLUGIN_GOOD + " --frame-graph test-frame");
  EXPECT_TRUE(plan.kept.count("test-post"));
  const auto plain = planOf(std::string("--plugin ") + SG_PLUGIN_GOOD);
  EXPECT_FALSE(plain.kept.count("test-post")) << "a registered pass runs only in frames that name it";
}

// A layer whose GLSL does not compile: the plugin, the author's own file and
// line, glslang's message; exit 1, no crash, in both shading paths.
TEST(Cli, BrokenLayerGlslIsReportedInTheAuthorsFile) {
  for (const char* mode : {"decoupled", "forward"}) {
    auto r = run(std::string("render --size 64x64 --frames 1 -o ") + (tempDir() / "broken.png").string() +
                 " --plugin " + SG_PLUGIN_BROKEN_GLSL + " --material broken --mode " + mode);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("(plugin 'test-broken-glsl')"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("broken-glsl/broken.glsl:6:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("brightnes"), std::string::npos) << r.output;
  }
}

TEST(Cli, GraphDotIsAGraphvizDigraph) {
  auto r = run("graph --dot --size 64x64");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.rfind("digraph", 0), 0u) << r.output.substr(0, 200);
}

// A failing command says why in exactly one line and exits 1.
void expectOneLineError(const Run& r, const std::string& mentions) {
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(r.output.rfind("shadelgraph: error: ", 0), 0u) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line: " << r.output;
  EXPECT_NE(r.output.find(mentions), std::string::npos) << mentions << " missing from: " << r.output;
}

struct BadCommand {
  const char* name;
  const char* args;
  const char* mentions;  // what the one line must name
};

// Each is refused before a scene is loaded or a device started.
const BadCommand kBadCommands[] = {
    {"UnknownOption", "render --bogus", "--bogus"},
    {"UnknownSubcommand", "frobnicate", "frobnicate"},
    {"NoSubcommand", "", "subcommand"},
    {"MissingValue", "render --size", "--size"},
    {"CameraNotANumber", "render --camera abc", "--camera"},
    {"FilterOutOfRange", "render --filter 7", "--filter"},
    {"ModeNotAMember", "render --mode sideways", "--mode"},
    {"SizeTrailingJunk", "render --size 64x64junk", "--size '64x64junk'"},
    {"SizeWrapsPast32Bits", "render --size 4294967360x64", "--size '4294967360x64'"},
    {"SizeZero", "render --size 0x64", "--size"},
    {"SizeAboveLimit", "render --size 16385x64", "16384"},
    {"SizeWithSign", "render --size +64x64", "--size"},
    {"SizeWithSpace", "render --size '64x 64'", "--size"},
    {"GraphSizeTrailingJunk", "graph --size 64x64junk", "--size"},
    {"StorageNan", "render --storage nan", "--storage nan"},
    {"StorageInf", "render --storage inf", "--storage inf"},
    {"StorageHuge", "render --storage 1e30", "--storage 1e+30"},
    {"StorageZero", "render --storage 0", "--storage 0"},
    {"CameraNegative", "render --camera -5", "--camera -5"},
    {"FrameNegative", "render --frame -5", "--frame -5"},
    {"PathNegative", "render --frame 1 --path -1", "--path -1"},
    {"BiasNan", "render --bias nan", "--bias nan"},
    {"BiasInf", "render --bias inf", "--bias inf"},
    {"BiasMinusInf", "render --bias=-inf", "--bias -inf"},
    {"BiasHuge", "render --bias 1e30", "--bias"},
    {"FramesZero", "render --frames 0", "--frames 0"},
    {"SoakEveryZero", "render --soak-every 0", "--soak-every 0"},
    {"ShadeRateZero", "render --shade-rate 0", "--shade-rate 0"},
    {"ShadeRateNegative", "render --shade-rate -2", "--shade-rate -2"},
    {"ShadeRateNotANumber", "render --shade-rate fast", "--shade-rate"},
    {"FramesInFlightThree", "render --frames-in-flight 3", "--frames-in-flight 3"},
    {"ShadeBudgetZero", "render --shade-budget 0", "--shade-budget 0"},
    {"ShadeBudgetNan", "render --shade-budget nan", "--shade-budget nan"},
    {"ShadeBudgetWithShadeRate", "render --shade-budget 5 --shade-rate 2", "--shade-rate"},
    {"BenchShadeRatesZero", "bench --shade-rates 1,0", "--shade-rates 0"},
    {"BenchPathFramesOne", "bench --shade-rates 2 --path-frames 1", "--path-frames 1"},
    {"BenchFramesInFlightThree", "bench --shade-rates 2 --frames-in-flight 3", "--frames-in-flight 3"},
    {"BenchFlickerFramesZero", "bench --flicker-frames 0", "--flicker-frames 0"},
    {"BenchFlickerFramesNegative", "bench --flicker-frames -3", "--flicker-frames -3"},
    {"BenchRepetitionsZero", "bench --repetitions 0", "--repetitions 0"},
    {"BenchReferenceScaleZero", "bench --reference-scale 0", "--reference-scale 0"},
    {"BenchReferenceBeyondSizeLimit", "bench --sizes 8192x8192 --reference-scale 4", "--reference-scale 4"},
    {"BenchSizesTrailingJunk", "bench --sizes 64x36junk", "--sizes '64x36junk'"},
    {"BenchSceneRatiosOneScene", "bench --scene-ratios", "--scene-ratios"},
    {"BenchLightCountsZero", "bench --effects --light-counts 8,0", "--light-counts 0"},
    {"BenchLightCountsBeyondLightBuffer", "bench --effects --light-counts 5000", "--light-counts 5000"},
    {"BenchEffectGroupUnknown", "bench --effects --effect-groups shadows,fog", "--effect-groups: unknown 'fog'"},
};

// Readable in gtest's and ctest's listings: the command line, not the struct's bytes.
void PrintTo(const BadCommand& c, std::ostream* os) { *os << "shadelgraph " << c.args; }

class CliRejects : public testing::TestWithParam<BadCommand> {};

TEST_P(CliRejects, WithOneLineAndExitCode1) { expectOneLineError(run(GetParam().args), GetParam().mentions); }

INSTANTIATE_TEST_SUITE_P(BadOptions, CliRejects, testing::ValuesIn(kBadCommands),
                         [](const testing::TestParamInfo<BadCommand>& param) { return std::string(param.param.name); });

TEST(Cli, HelpStatesTheLimitsAndExits0) {
  auto help = run("render --help");
  EXPECT_EQ(help.exitCode, 0) << help.output;
  for (const char* limit : {"16384", "-8 to 8", "1.25 to 64", "--soak-report"})
    EXPECT_NE(help.output.find(limit), std::string::npos) << limit << " missing from:\n" << help.output;
  auto benchHelp = run("bench --help");
  EXPECT_EQ(benchHelp.exitCode, 0) << benchHelp.output;
  EXPECT_NE(benchHelp.output.find("2 or more"), std::string::npos) << benchHelp.output;
}

TEST(Cli, CameraBeyondTheScenesCamerasIsNamedAsTheOption) {
  expectOneLineError(run("render --size 32x32 --camera 3 -o " + (tempDir() / "camera.png").string()),
                     "--camera 3: the scene has 1 camera(s)");  // the default scene's own
}

nlohmann::json statsOf(const std::string& args, const std::string& name) {
  const auto stats = tempDir() / (name + ".json");
  std::filesystem::remove(stats);
  auto r = run("render --mode decoupled --size 96x64 --frames 1 --storage 16 -o " + (tempDir() / (name + ".png")).string() +
               " --stats " + stats.string() + " " + args);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(stats);
  return nlohmann::json::parse(in);
}

// --shade-rate 3 over 5 frames: frames 0 and 3 shade, the others reuse (a
// static camera and, with --still, a static gold sphere fill nothing); the
// stats count it and nothing is missed.
TEST(Cli, ShadeRateStatsCountShadeFramesAndReuse) {
  const auto stats = tempDir() / "shade-rate.json";
  std::filesystem::remove(stats);
  auto r = run("render --mode decoupled --size 96x64 --frames 5 --still --shade-rate 3 --storage 16 -o " +
               (tempDir() / "shade-rate.png").string() + " --stats " + stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(stats);
  const auto json = nlohmann::json::parse(in);
  EXPECT_EQ(json["raster_frames"], 5);
  EXPECT_EQ(json["shade_frames"], 2);
  // The GPU time of every raster frame, in order.
  ASSERT_TRUE(json["frames_ms"].is_array());
  ASSERT_EQ(json["frames_ms"].size(), 5u);
  for (const auto& ms : json["frames_ms"]) EXPECT_GT(ms.get<double>(), 0.0);
  EXPECT_EQ(json["frames_ms"].back(), json["gpu_ms"]) << "the last frame is the one reported";
  EXPECT_EQ(json["shadels_filled"], 0);
  EXPECT_GT(json["shadels_reused"].get<double>(), 0.0);
  EXPECT_EQ(json["shadels_reused_last_frame"], json["shadels_allocated"]) << "frame 4 reuses every stored shadel";
  EXPECT_EQ(json["shadels_stale_max_age"], 1) << "frame 4 reads frame 3's shading";
  EXPECT_EQ(json["composite_misses"], 0);
}

// Without --still the default scene's gold sphere moves a frame at a time:
// it is reshaded in the frames between shade frames (the fill), still with no miss.
TEST(Cli, TheDefaultScenesMovingSphereIsReshadedBetweenShadeFrames) {
  const auto stats = tempDir() / "shade-rate-moving.json";
  std::filesystem::remove(stats);
  auto r = run("render --mode decoupled --size 96x64 --frames 5 --shade-rate 3 --storage 16 -o " +
               (tempDir() / "shade-rate-moving.png").string() + " --stats " + stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(stats);
  const auto json = nlohmann::json::parse(in);
  EXPECT_GT(json["shadels_filled"].get<double>(), 0.0) << "the sphere moved";
  EXPECT_GT(json["shadels_reused"].get<double>(), 0.0) << "the rest did not";
  EXPECT_EQ(json["composite_misses"], 0);
}

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// --frames N ends at frame 0 (no --frame): the written image is frame 0's
// pose of the moving objects however many frames ran before it.
TEST(Cli, TheWrittenFrameIsFrame0WhateverFrames) {
  const auto one = tempDir() / "frame0-once.png", three = tempDir() / "frame0-thrice.png",
             still = tempDir() / "frame0-still.png";
  ASSERT_EQ(run("render --mode forward --size 96x64 --frames 1 -o " + one.string()).exitCode, 0);
  ASSERT_EQ(run("render --mode forward --size 96x64 --frames 3 -o " + three.string()).exitCode, 0);
  ASSERT_EQ(run("render --mode forward --size 96x64 --frames 3 --still -o " + still.string()).exitCode, 0);
  EXPECT_FALSE(fileBytes(one).empty());
  EXPECT_EQ(fileBytes(one), fileBytes(three));
  EXPECT_EQ(fileBytes(one), fileBytes(still));
}

// Budget mode: no shade frames after the first, what the budget leaves stale
// is reported, nothing is missed.
TEST(Cli, ShadeBudgetReportsWhatItLeftStale) {
  const auto stats = tempDir() / "shade-budget.json";
  std::filesystem::remove(stats);
  auto r = run("render --mode decoupled --size 96x64 --frames 4 --still --shade-budget 0.05 --storage 16 -o " +
               (tempDir() / "shade-budget.png").string() + " --stats " + stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("shade budget 0.05 ms"), std::string::npos) << r.output;
  std::ifstream in(stats);
  const auto json = nlohmann::json::parse(in);
  EXPECT_EQ(json["shade_frames"], 1);
  EXPECT_EQ(json["raster_frames"], 4);
  for (const char* key : {"shadels_left_stale", "shadels_refreshed", "shadels_stale_max_age", "stale_age_limit"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_GT(json["shadels_left_stale"].get<double>(), 0.0) << "0.05 ms does not pay for the whole scene";
  EXPECT_GE(json["shadels_stale_max_age"].get<int>(), 1);
  EXPECT_EQ(json["composite_misses"], 0);
}

// A trace of several frames holds each frame's passes on its queue's GPU
// track, on one clock (later frames later), and each frame's host span.
TEST(Cli, TraceOfSeveralFramesPutsThemOnOneClock) {
  const auto trace = tempDir() / "frames-trace.json";
  std::filesystem::remove(trace);
  auto r = run("render --mode decoupled --size 96x64 --frames 3 --storage 16 -o " + (tempDir() / "frames-trace.png").string() +
               " --trace " + trace.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(trace);
  const auto json = nlohmann::json::parse(in);
  std::map<int, std::string> tracks;
  for (const auto& e : json["traceEvents"])
    if (e["ph"] == "M") tracks[e["tid"].get<int>()] = e["args"]["name"];
  std::vector<double> composites, frameSpans;
  for (const auto& e : json["traceEvents"]) {
    if (e["ph"] != "X") continue;
    const std::string track = tracks[e["tid"].get<int>()];
    if (track == "GPU Graphics" && e["name"] == "composite") composites.push_back(e["ts"].get<double>());
    if (track == "CPU frames") frameSpans.push_back(e["ts"].get<double>());
  }
  ASSERT_EQ(composites.size(), 3u) << "one composite per frame";
  EXPECT_LT(composites[0], composites[1]);
  EXPECT_LT(composites[1], composites[2]);
  EXPECT_EQ(frameSpans.size(), 3u);
}

// Two frames in flight at shade rate 2: the shade frames run as their frames'
// tails on the async-compute track (timed once done), nothing is missed.
TEST(Cli, FramesInFlightTraceShowsShadeFramesOnAsyncCompute) {
  const auto trace = tempDir() / "in-flight-trace.json";
  const auto stats = tempDir() / "in-flight-stats.json";
  auto r = run("render --mode decoupled --size 96x64 --frames 5 --shade-rate 2 --frames-in-flight 2 --storage 16 -o " +
               (tempDir() / "in-flight.png").string() + " --trace " + trace.string() + " --stats " + stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(trace);
  const auto json = nlohmann::json::parse(in);
  std::map<int, std::string> tracks;
  for (const auto& e : json["traceEvents"])
    if (e["ph"] == "M") tracks[e["tid"].get<int>()] = e["args"]["name"];
  int shadeFrames = 0;
  for (const auto& e : json["traceEvents"])
    if (e["ph"] == "X" && tracks[e["tid"].get<int>()] == "GPU AsyncCompute" && e["name"] == "shade-frame layer-shade")
      ++shadeFrames;
  EXPECT_EQ(shadeFrames, 3) << "frames 0, 2 and 4";
  std::ifstream statsIn(stats);
  const auto s = nlohmann::json::parse(statsIn);
  EXPECT_EQ(s["composite_misses"], 0);
  EXPECT_EQ(s["frames_ms"].size(), 5u);
}

// A negative bias is a fixed bias too (finer shadels), not the adjuster.
TEST(Cli, NegativeBiasShadesFinerThanZero) {
  const auto zero = statsOf("--bias 0", "bias-zero");
  const auto finer = statsOf("--bias -1", "bias-minus-one");
  ASSERT_TRUE(finer["global_bias"].is_number()) << finer["global_bias"];
  EXPECT_EQ(finer["global_bias"].get<double>(), -1.0);
  EXPECT_EQ(zero["global_bias"].get<double>(), 0.0);
  // One level finer: up to 4x the shadels; at least twice as many on this scene.
  EXPECT_GT(finer["shadels_marked"].get<double>(), 2.0 * zero["shadels_marked"].get<double>());
  EXPECT_EQ(finer["composite_misses"], 0);
}

// Output that cannot be written fails the command with one line naming the
// file (besides whatever was printed before, e.g. the timing table).
TEST(Cli, WritingToAFullDiskFailsNamingThePath) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "/dev/full not present";
  const std::string base = "render --size 32x32 --frames 1 ";
  const std::string png = " -o " + (tempDir() / "full.png").string();
  for (const std::string& args : {base + "-o /dev/full", base + png + " --stats /dev/full",
                                  base + png + " --trace /dev/full", base + png + " --soak-report /dev/full --soak-every 1"}) {
    auto r = run(args);
    EXPECT_EQ(r.exitCode, 1) << args << ": " << r.output;
    EXPECT_NE(r.output.find("shadelgraph: error: /dev/full: cannot write"), std::string::npos) << args << ": " << r.output;
    EXPECT_EQ(r.output.find("shadelgraph: error:"), r.output.rfind("shadelgraph: error:")) << "one error: " << r.output;
  }
  // Stdout too: a plan that did not arrive is a failure.
  auto plan = run("graph --size 32x32", "&1", " >/dev/full");
  EXPECT_EQ(plan.exitCode, 1) << plan.output;
  EXPECT_NE(plan.output.find("shadelgraph: error: stdout: write failed"), std::string::npos) << plan.output;
}

}  // namespace
