// Composing frames from the command line: `passes`, `--frame-graph` with a
// registered name or a file, its one-line errors, and `--object-mode`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "procedural_sky.hpp"
#include "test_support.hpp"

namespace {

sg::test::CliOutputs run(const std::string& args) {
  return sg::test::runCliApart(args, std::filesystem::temp_directory_path() / "sg-frame-cli-stderr.txt");
}

std::filesystem::path writeFrame(const std::string& name, const std::string& json) {
  const auto path = std::filesystem::temp_directory_path() / ("sg-frame-" + name + ".json");
  std::ofstream(path) << json;
  return path;
}

// The passes the compiled graph keeps.
std::set<std::string> keptPasses(const std::string& args) {
  const auto r = run("graph --json --size 96x64 " + args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::set<std::string> kept;
  const auto plan = nlohmann::json::parse(r.out);  // kept alive: the loop walks a part of it
  for (const auto& p : plan["passes"])
    if (!p["culled"].get<bool>()) kept.insert(p["name"].get<std::string>());
  return kept;
}

TEST(FrameCli, PassesListsEveryRegisteredPassWithItsResourcesAndTheFrames) {
  const auto r = run(std::string("passes --json --plugin ") + SG_PLUGIN_GOOD);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto json = nlohmann::json::parse(r.out);
  std::map<std::string, nlohmann::json> passes;
  for (const auto& p : json["passes"]) passes[p["name"].get<std::string>()] = p;
  for (const char* name : {"skinning", "z-prepass", "light-cull", "forward-opaque", "alpha-mask", "alpha-blend", "exposure", "tonemap",
                           "shadel-clear", "shadel-mark", "support-expand", "shadel-allocate", "work-aggregate",
                           "layer-shade", "composite", "counters-readback", "decoupled-debug-view", "test-post"})
    EXPECT_TRUE(passes.count(name)) << name;
  EXPECT_EQ(passes["composite"]["reads"], nlohmann::json({"scene.hdr", "scene.depth", "shadel.shaded", "shadel.remap",
                                                          "shadel.counters"}));
  EXPECT_EQ(passes["composite"]["parameters"][0]["name"], "filter");
  EXPECT_EQ(passes["exposure"]["queue"], "AsyncCompute");
  EXPECT_EQ(passes["test-post"]["plugin"], "test-good");
  EXPECT_EQ(passes["tonemap"]["plugin"], "built-in");
  EXPECT_EQ(json["frames"]["forward"],
            nlohmann::json({"skinning", "z-prepass", "object-pick", "shadows", "environment", "light-cull", "forward-opaque",
                            "alpha-mask", "environment-background", "alpha-blend", "exposure", "bloom", "tonemap"}));
  EXPECT_EQ(passes["object-pick"]["writes"], nlohmann::json({"view.pick"}));
  EXPECT_EQ(passes["skinning"]["writes"], nlohmann::json({"scene.vertices"}));
  const auto& plugged = json["frames"]["test-frame"];
  ASSERT_TRUE(plugged.is_array());
  EXPECT_EQ(plugged[plugged.size() - 4], "test-post") << "before exposure: " << plugged.dump();
}

// A scene file naming an environment image: the compiled frame holds the
// prefilter (graph --json shows the first frame), render writes the picture;
// the same scene without it holds no environment pass.
TEST(FrameCli, AnEnvironmentImageAddsThePrefilterOnlyWhenNamed) {
  SG_REQUIRE_ASSETS();
  sg::test::TempDir dir;
  sg::bench::writeProceduralSky(dir.path() / "sky.hdr", 64, 32);
  const std::string model = sg::test::samplePath("EnvironmentTest").string();
  const auto lit = dir.write("lit.json", R"({"objects": [{"gltf": ")" + model +
                                             R"("}], "environment": {"image": "sky.hdr", "intensity": 2}})");
  const auto plain = dir.write("plain.json", R"({"objects": [{"gltf": ")" + model + R"("}]})");
  for (const char* mode : {"forward", "decoupled"}) {
    const auto withEnv = keptPasses(lit.string() + " --mode " + mode);
    EXPECT_TRUE(withEnv.count("environment-downsample") && withEnv.count("environment-prefilter")) << mode;
    for (const auto& name : keptPasses(plain.string() + " --mode " + mode))
      EXPECT_EQ(name.rfind("environment", 0), std::string::npos) << mode << ": " << name;
  }
  const auto out = dir.path() / "lit.png";
  const auto r = run("render " + lit.string() + " --size 160x90 --frames 2 -o " + out.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out));
}

// The object-pick pass is in both frames, but its graph passes (a 1x1 id
// target and its readback) are in a frame only while a pick is pending.
TEST(FrameCli, ThePickPassIsInTheFrameOnlyWhileAPickIsPending) {
  for (const char* frame : {"forward", "decoupled"}) {
    const auto normal = keptPasses(std::string("--frame-graph ") + frame);
    const auto picking = keptPasses(std::string("--frame-graph ") + frame + " --pick 48,32");
    EXPECT_FALSE(normal.count("object-pick")) << frame;
    EXPECT_FALSE(normal.count("object-pick readback")) << frame;
    EXPECT_TRUE(picking.count("object-pick")) << frame;
    EXPECT_TRUE(picking.count("object-pick readback")) << frame;
    std::set<std::string> rest = picking;
    rest.erase("object-pick");
    rest.erase("object-pick readback");
    EXPECT_EQ(rest, normal) << frame << ": a pick adds its own passes and nothing else";
  }
  const auto outside = run("graph --size 96x64 --pick 96,0");
  EXPECT_EQ(outside.exitCode, 1);
  EXPECT_EQ(outside.err, "shadelgraph: error: --pick x 96: must be at most 95\n");
}

// The frame holds only the passes the scene needs: with no object shaded
// forward, forward-opaque (it would only clear the colour) is not in the
// decoupled frame and composite clears instead; one forward object brings it back.
TEST(FrameCli, ForwardOpaqueIsInTheFrameOnlyWithAnObjectShadedForward) {
  const auto decoupled = keptPasses("--mode decoupled");
  EXPECT_FALSE(decoupled.count("forward-opaque"));
  EXPECT_TRUE(decoupled.count("composite"));
  EXPECT_TRUE(keptPasses("--mode decoupled --object-mode \"gold sphere=forward\"").count("forward-opaque"));
  EXPECT_TRUE(keptPasses("--mode forward").count("forward-opaque"));
}

// Without composite in the frame nothing else would clear the colour of a
// frame whose objects are all decoupled: forward-opaque clears it.
TEST(FrameCli, AFrameWithoutCompositeStillClearsTheColour) {
  const auto file = writeFrame("no-composite", R"({"name": "no-composite", "base": "decoupled", "remove": ["composite"]})");
  const auto kept = keptPasses("--mode decoupled --frame-graph " + file.string());
  EXPECT_TRUE(kept.count("forward-opaque"));
  EXPECT_FALSE(kept.count("composite"));
  const auto png = std::filesystem::temp_directory_path() / "sg-frame-no-composite.png";
  const auto r = run("render --size 64x64 --mode decoupled --frame-graph " + file.string() + " -o " + png.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
}

TEST(FrameCli, TheForwardFrameHoldsNoDecoupledPass) {
  const auto kept = keptPasses("--mode decoupled --frame-graph forward");
  EXPECT_TRUE(kept.count("forward-opaque"));
  for (const auto& name : kept) EXPECT_EQ(name.rfind("shadel-", 0), std::string::npos) << name;
  EXPECT_FALSE(kept.count("composite"));
}

TEST(FrameCli, AFrameFileEditsARegisteredFrame) {
  // The plugin's pass after alpha-blend in the forward frame, exposure's
  // neighbour removed: graph and render both take the file.
  const auto file = writeFrame("edited", R"({"name": "edited", "base": "forward",
      "passes": [{"pass": "test-post", "after": "alpha-blend"}], "remove": ["alpha-mask"]})");
  const auto kept = keptPasses(std::string("--plugin ") + SG_PLUGIN_GOOD + " --frame-graph " + file.string());
  EXPECT_TRUE(kept.count("test-post"));
  const auto png = std::filesystem::temp_directory_path() / "sg-frame-edited.png";
  const auto r = run(std::string("render --size 64x64 --plugin ") + SG_PLUGIN_GOOD + " --frame-graph " + file.string() +
                     " -o " + png.string());
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
}

// Each broken frame: exit 1 and exactly one line naming the frame, the pass and the resource.
TEST(FrameCli, ABrokenFrameFailsWithOneLineNamingPassAndResource) {
  struct Case {
    const char* json;
    const char* problem;  // after "frame 'f' (<file>): "
  };
  const Case cases[] = {
      {R"({"name": "f", "passes": ["z-prepass", "tonemap"]})",
       "pass 'tonemap' reads 'scene.hdr', which no pass of the frame writes"},
      {R"({"name": "f", "base": "forward", "passes": ["lens-flare"]})", "unknown pass 'lens-flare'"},
      {R"({"name": "f", "passes": ["z-prepass", "forward-opaque", "tonemap", "exposure"]})",
       "pass 'tonemap' reads 'scene.exposure', which only 'exposure' writes, after it"},
      {R"({"name": "f", "base": "forward", "passes": [{"pass": "test-post", "after": "tonemap", "before": "exposure"}]})",
       "after/before constraints (and the resources they read) form a cycle"},
  };
  int i = 0;
  for (const auto& c : cases) {
    const auto file = writeFrame("broken-" + std::to_string(i++), c.json);
    const std::string expected = "frame 'f' (" + file.string() + "): " + c.problem;
    const auto r = run(std::string("render --size 32x32 --plugin ") + SG_PLUGIN_GOOD + " --frame-graph " +
                       file.string() + " -o /dev/null");
    EXPECT_EQ(r.exitCode, 1) << c.json;
    const std::string line = r.err.substr(r.err.find("shadelgraph: error:"));
    EXPECT_NE(line.find(expected), std::string::npos) << line;
    EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1) << line;
  }
  // An exposure parameter out of its range: one line naming the pass and the parameter.
  for (const char* exposure : {R"({"mode": "sideways"})", R"({"adaptation": 0.0})", R"({"ev100": 1e9})"}) {
    const auto file = writeFrame("bad-exposure", std::string(R"({"name": "f", "base": "forward", "parameters": {"exposure": )") +
                                                     exposure + "}}");
    const auto bad = run("render --size 32x32 --frame-graph " + file.string() + " -o /dev/null");
    EXPECT_EQ(bad.exitCode, 1) << exposure;
    const std::string line = bad.err.substr(std::min(bad.err.find("shadelgraph: error:"), bad.err.size()));
    EXPECT_NE(line.find("pass 'exposure': parameter '"), std::string::npos) << line;
    EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1) << line;
  }
  const auto r = run("graph --frame-graph no-such-frame");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("no such file, and no frame of that name (known: decoupled, forward)"), std::string::npos)
      << r.err;
}

TEST(FrameCli, ObjectModeSetsOneObjectOverTheGlobalMode) {
  const auto stats = std::filesystem::temp_directory_path() / "sg-frame-object-mode.json";
  auto r = run("render --size 96x64 --frames 1 --mode decoupled --object-mode \"gold sphere=forward\" -o /dev/null --stats " +
               stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto s = nlohmann::json::parse(std::ifstream(stats));
  const auto all = s["objects_forward"].get<int>() + s["objects_decoupled"].get<int>();
  EXPECT_EQ(s["objects_forward"], 1) << "only the gold sphere";
  r = run("render --size 96x64 --frames 1 --mode forward --object-mode torus=decoupled -o /dev/null --stats " +
          stats.string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  s = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(s["objects_decoupled"], 1) << "only the torus";
  EXPECT_EQ(s["objects_forward"].get<int>() + s["objects_decoupled"].get<int>(), all);
  r = run("graph --object-mode dragon=forward");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--object-mode dragon=forward: the scene has no object 'dragon'"), std::string::npos) << r.err;
  r = run("graph --object-mode torus=sideways");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("expected NAME=forward|decoupled|auto"), std::string::npos) << r.err;
}

}  // namespace
