// glTF animations from the command line: --time poses the scene (at the last
// of --frames; those before step back 1/--fps each), --animation chooses; in
// both shading paths, validation on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadelgraph/image/png.hpp>

#include "cli_run.hpp"
#include "test_support.hpp"

namespace {

std::filesystem::path tempDir() {
  static const sg::test::TempDir dir;
  return dir.path();
}

struct Rendered {
  sg::image::Rgba8Image image;
  nlohmann::json stats;
};

Rendered render(const std::string& args, const std::string& name) {
  const auto png = tempDir() / (name + ".png");
  const auto stats = tempDir() / (name + ".json");
  const auto r = sg::test::runCli("render " + sg::test::samplePath("BoxAnimated").string() + " --size 96x72 -o " +
                                  png.string() + " --stats " + stats.string() + " " + args);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(stats);
  return {sg::image::readPng(png), nlohmann::json::parse(in)};
}

// Pixels that differ by more than 8/255 in some channel.
size_t differingPixels(const sg::image::Rgba8Image& a, const sg::image::Rgba8Image& b) {
  size_t count = 0;
  for (size_t i = 0; i + 3 < std::min(a.pixels.size(), b.pixels.size()); i += 4)
    for (size_t c = 0; c < 3; ++c)
      if (std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > 8) {
        ++count;
        break;
      }
  return count;
}

class AnimationCli : public testing::TestWithParam<const char*> {};

// BoxAnimated: the inner box rises out of the outer one and turns.
TEST_P(AnimationCli, TimePosesTheSceneAndFramesPlayIt) {
  SG_REQUIRE_ASSETS();
  const std::string mode = std::string("--mode ") + GetParam();
  const Rendered start = render(mode + " --time 0 --frames 1", "start");
  const Rendered later = render(mode + " --time 1.2 --frames 1", "later");
  const Rendered again = render(mode + " --time 1.2 --frames 1", "again");
  EXPECT_GT(differingPixels(start.image, later.image), 96u * 72u / 50) << "the boxes moved";
  EXPECT_EQ(differingPixels(later.image, again.image), 0u) << "a time is one pose";
  const Rendered played = render(mode + " --time 1.2 --fps 10 --frames 3", "played");  // at 1.0, 1.1 and 1.2 s
  EXPECT_GT(differingPixels(played.image, start.image), 96u * 72u / 50);
  // Every object with its shading and the reason, as --mode asked.
  ASSERT_EQ(played.stats["objects"].size(), 2u) << played.stats.dump();
  for (const auto& object : played.stats["objects"]) {
    EXPECT_EQ(object["shading"], GetParam()) << object.dump();
    EXPECT_FALSE(object["reason"].get<std::string>().empty()) << object.dump();
  }
  if (std::string(GetParam()) == "decoupled") {
    EXPECT_EQ(played.stats["objects_decoupled"], 2) << played.stats.dump();
    EXPECT_EQ(played.stats["composite_misses"], 0) << played.stats.dump();
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, AnimationCli, testing::Values("forward", "decoupled"),
                         [](const testing::TestParamInfo<const char*>& param) { return std::string(param.param); });

TEST(AnimationCliInspect, ListsEveryAnimationWithItsChannels) {
  SG_REQUIRE_ASSETS();
  const auto r = sg::test::runCli("inspect " + sg::test::samplePath("InterpolationTest").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* line : {"animation 'Step Scale': ", " scale STEP", "animation 'CubicSpline Rotation': ",
                           " rotation CUBICSPLINE", "animation 'Linear Translation': ", " translation LINEAR"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << " missing from:\n" << r.output;
}

// CesiumMan off screen, its shadow on the ground in view: the shadow map
// holds its pose at --time (the skinning pass runs for a deformed caster of a
// shadow map in view, not only for visible deformed objects).
TEST(AnimationCliShadows, AnOffScreenSkinnedCasterCastsItsCurrentPose) {
  SG_REQUIRE_ASSETS();
  const auto scene = tempDir() / "offscreen-caster.json";
  std::ofstream(scene) << R"({"objects": [{"gltf": ")" << sg::test::samplePath("Box").string()
                       << R"(", "translation": [2, -0.01, 0], "scale": [12, 0.02, 12]},
      {"gltf": ")" << sg::test::samplePath("CesiumMan").string() << R"(", "name": "walker"}],
    "lights": [{"type": "directional", "direction": [1, -0.5, 0], "intensity": 3, "shadows": true}],
    "cameraPaths": [{"type": "keys", "keys": [{"t": 0, "position": [3.5, 3, 1], "target": [3.5, 0, 0]}]}]})";
  for (const char* mode : {"forward", "decoupled"}) {
    std::vector<sg::image::Rgba8Image> images;
    for (const char* time : {"0.3", "1.0"}) {
      const auto png = tempDir() / (std::string("offscreen-") + mode + "-" + time + ".png");
      const auto r = sg::test::runCli("render " + scene.string() + " --frame 0 --size 160x90 --frames 1 --mode " + mode +
                                      " --time " + time + " -o " + png.string());
      ASSERT_EQ(r.exitCode, 0) << r.output;
      // Decoupled, the walker would be the second decoupled object if it were drawn.
      if (std::string(mode) == "decoupled") {
        EXPECT_NE(r.output.find("2 draws, 1 objects decoupled"), std::string::npos) << "the walker is culled: " << r.output;
      }
      images.push_back(sg::image::readPng(png));
    }
    EXPECT_GT(differingPixels(images[0], images[1]), 160u * 90u / 100) << mode << ": the shadow keeps one pose";
  }
}

// bench --play: forward and decoupled alternated along the playback, each
// frame posed (the boxes move), medians and decoupled's shadels per pixel.
TEST(AnimationCliBench, PlayTimesBothPathsAlongThePlayback) {
  SG_REQUIRE_ASSETS();
  const auto dir = tempDir() / "bench-play";
  const auto r = sg::test::runCli("bench " + sg::test::samplePath("BoxAnimated").string() + " --play 3 --sizes 96x72 --out " +
                                  dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json")) << "--play replaces the configuration sweep";
  std::ifstream in(dir / "playback.json");
  const auto json = nlohmann::json::parse(in);
  ASSERT_EQ(json["runs"].size(), 1u);
  const auto& configs = json["runs"][0]["configs"];
  ASSERT_EQ(configs.size(), 2u);
  for (const auto& c : configs) {
    EXPECT_EQ(c["frame_ms_samples"].size(), 3u) << c.dump();
    EXPECT_GT(c["frame_ms_median"].get<double>(), 0.0) << c.dump();
  }
  EXPECT_EQ(configs[0]["config"], "forward");
  EXPECT_EQ(configs[0]["objects_decoupled"], 0);
  EXPECT_DOUBLE_EQ(configs[0]["ratio_to_forward"].get<double>(), 1.0);
  EXPECT_EQ(configs[1]["config"], "decoupled");
  EXPECT_EQ(configs[1]["objects_decoupled"], 2) << "both boxes, deforming or not";
  EXPECT_GT(configs[1]["shadels_per_pixel_median"].get<double>(), 0.0);
  EXPECT_EQ(configs[1]["composite_misses"], 0) << configs[1].dump();
}

void expectOneLineError(const sg::test::CliRun& r, const std::string& mentions) {
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(r.output.rfind("shadelgraph: error: ", 0), 0u) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one line: " << r.output;
  EXPECT_NE(r.output.find(mentions), std::string::npos) << mentions << " missing from: " << r.output;
}

TEST(AnimationCliErrors, BadChoicesFailWithOneLine) {
  expectOneLineError(sg::test::runCli("render --time nan"), "--time nan");
  expectOneLineError(sg::test::runCli("render --fps 0"), "--fps 0");
  expectOneLineError(sg::test::runCli("render --size 32x32 --animation walk -o " + (tempDir() / "x.png").string()),
                     "--animation walk: the scene has no animations");
  expectOneLineError(sg::test::runCli("bench --play 2 --sizes 32x18 --out " + (tempDir() / "play").string()),
                     "--play: default has no animations");
  SG_REQUIRE_ASSETS();
  expectOneLineError(sg::test::runCli("render " + sg::test::samplePath("InterpolationTest").string() +
                                      " --size 32x32 --animation 'Bounce' -o " + (tempDir() / "y.png").string()),
                     "--animation Bounce: the scene's animations are 0 'Step Scale', 1 'Linear Scale'");
}

}  // namespace
