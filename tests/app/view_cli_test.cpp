// shadelgraph view, driven by --script under Xvfb: picking, debug views
// against render, resizing, and its bad input. Runs with SG_VALIDATION=1 (set
// by ctest for device tests): the viewer exits 1 on any validation message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <shadelgraph/image/png.hpp>

#include "cli_run.hpp"
#include "test_support.hpp"
#include "xvfb_display.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path kMixedScene = fs::path(SG_SOURCE_DIR) / "tests/scenes/mixed.json";

class ViewCli : public ::testing::Test {
 protected:
  // The X server, started once per test process (ctest runs each test alone).
  static sg::test::XvfbDisplay& display() {
    static sg::test::XvfbDisplay x;
    return x;
  }
  void SetUp() override { ASSERT_TRUE(display().ok()) << display().error(); }

  sg::test::CliRun view(const std::string& args, const std::string& script) {
    const auto file = dir_.write("script.txt", script);
    return sg::test::runCli("view " + args + " --script " + file.string());
  }
  sg::test::TempDir dir_;
};

// Pixels whose largest channel difference is above `noise`.
size_t differing(const sg::image::Rgba8Image& a, const sg::image::Rgba8Image& b, int noise) {
  size_t n = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])) > noise) {
        ++n;
        break;
      }
  return n;
}

size_t lines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }

TEST(ViewCliNoDisplay, SaysSoInOneLineAndExits1) {
  const auto r = sg::test::runShell("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(SG_CLI) +
                                    " view --size 160x90 2>&1");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lines(r.output), 1u) << r.output;
  EXPECT_EQ(r.output.rfind("shadelgraph: error: no display", 0), 0u) << r.output;
}

TEST(ViewCliNoDisplay, AnUnknownScriptEventNamesTheFileAndLine) {
  sg::test::TempDir dir;
  const auto script = dir.write("bad.txt", "wait 1\n# a comment\njump 3\nquit\n");
  const auto r = sg::test::runCli("view --size 160x90 --script " + script.string());
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lines(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(script.string() + ":3: unknown event 'jump'"), std::string::npos) << r.output;
}

TEST_F(ViewCli, ASceneThatFailsToLoadGivesRendersError) {
  const std::string missing = (dir_.path() / "missing.gltf").string();
  const auto viewed = sg::test::runCli("view " + missing + " --size 160x90");
  const auto rendered = sg::test::runCli("render " + missing + " --size 160x90 -o " + (dir_.path() / "x.png").string());
  EXPECT_EQ(viewed.exitCode, 1);
  EXPECT_EQ(rendered.exitCode, 1);
  EXPECT_EQ(lines(viewed.output), 1u) << viewed.output;
  EXPECT_EQ(viewed.output, rendered.output);
}

// Orbit, click the helmet: it goes forward, the counters say so, and the
// image changes only about the middle of the view where the helmet stands
// (camera path 0 at frame 0 looks at it; the box is on the left, the engine on the right).
TEST_F(ViewCli, ClickingTheHelmetSwitchesItToForward) {
  SG_REQUIRE_ASSETS();
  const fs::path before = dir_.path() / "before.png", after = dir_.path() / "after.png";
  const auto r = view(kMixedScene.string() + " --frame 0 --size 320x180 --bias 0",
                      "wait 1\nmouse drag 160 90 175 85\nwait 1\nscreenshot " + before.string() +
                          "\nmouse click 160 90\nwait 2\nscreenshot " + after.string() + "\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto picked = r.output.find("pick 160 90: 'helmet");
  ASSERT_NE(picked, std::string::npos) << r.output;
  EXPECT_EQ(r.output.substr(r.output.find('\n', picked) - 10, 10), "-> forward") << r.output;
  const auto a = sg::image::readPng(before), b = sg::image::readPng(after);
  ASSERT_EQ(a.width, 320u);
  ASSERT_EQ(b.width, 320u);
  // The decoupled objects the counters report drop by one.
  const auto decoupledIn = [&](const fs::path& png) {
    const auto at = r.output.find("wrote " + png.string());
    return at == std::string::npos ? -1 : std::atoi(r.output.c_str() + r.output.find(", ", at) + 2);
  };
  EXPECT_EQ(decoupledIn(after), decoupledIn(before) - 1) << r.output;
  size_t changed = 0, outside = 0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const size_t i = (size_t(y) * a.width + x) * 4;
      int d = 0;
      for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])));
      if (d <= 3) continue;
      ++changed;
      if (x < a.width / 4 || x >= a.width * 3 / 4) ++outside;
    }
  EXPECT_GT(changed, 200u) << "forward shading should look different from decoupled somewhere on the helmet";
  EXPECT_EQ(outside, 0u) << changed << " pixels changed, " << outside << " of them beside the helmet";
}

// Key 2 switches to the level view: the viewer's frame is render --view level's.
TEST_F(ViewCli, TheDebugViewMatchesRender) {
  SG_REQUIRE_ASSETS();
  const fs::path viewed = dir_.path() / "viewed.png", rendered = dir_.path() / "rendered.png";
  const std::string frame = kMixedScene.string() + " --frame 0 --size 320x180 --bias 0";
  const fs::path record = dir_.path() / "record", shots = dir_.path() / "shots";
  const auto r = view(frame + " --record " + record.string() + " --screenshot-dir " + shots.string(),
                      "key 2\nwait 2\nscreenshot " + viewed.string() + "\nkey P\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("view: level"), std::string::npos) << r.output;
  // --record wrote every frame shown, P the frame as the script's screenshot.
  const auto shown = r.output.find("viewer: ");
  ASSERT_NE(shown, std::string::npos) << r.output;
  const auto frames = size_t(std::atoi(r.output.c_str() + shown + 8));
  EXPECT_GT(frames, 2u);
  EXPECT_EQ(size_t(std::distance(fs::directory_iterator(record), fs::directory_iterator())), frames);
  EXPECT_EQ(differing(sg::image::readPng(shots / "screenshot-000.png"), sg::image::readPng(viewed), 0), 0u);
  const auto rr = sg::test::runCli("render " + frame + " --view level -o " + rendered.string());
  ASSERT_EQ(rr.exitCode, 0) << rr.output;
  const auto a = sg::image::readPng(viewed), b = sg::image::readPng(rendered);
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_EQ(differing(a, b, 2), 0u);
}

// Two resizes: frames at each new size, the last one render's image at that size, validation clean.
TEST_F(ViewCli, ResizingTwiceRendersAtEachNewSize) {
  SG_REQUIRE_ASSETS();
  const fs::path large = dir_.path() / "large.png", small = dir_.path() / "small.png",
                 rendered = dir_.path() / "rendered.png";
  const std::string frame = kMixedScene.string() + " --frame 0 --bias 0";
  const auto r = view(frame + " --size 320x180", "wait 1\nresize 480 270\nwait 1\nscreenshot " + large.string() +
                                                     "\nresize 240 135\nwait 2\nscreenshot " + small.string() + "\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("size: 480x270"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("size: 240x135"), std::string::npos) << r.output;
  const auto l = sg::image::readPng(large), s = sg::image::readPng(small);
  EXPECT_EQ(l.width, 480u);
  EXPECT_EQ(l.height, 270u);
  ASSERT_EQ(s.width, 240u);
  ASSERT_EQ(s.height, 135u);
  const auto rr = sg::test::runCli("render " + frame + " --size 240x135 -o " + rendered.string());
  ASSERT_EQ(rr.exitCode, 0) << rr.output;
  EXPECT_EQ(differing(s, sg::image::readPng(rendered), 2), 0u);
}

}  // namespace
