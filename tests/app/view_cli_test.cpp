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

// Keys 2, 5 and 6 switch to the level view and every object in the uv-checker
// or triangle-id material: the viewer's frame is render's with --view level or
// --material of the same camera.
struct DebugViewCase {
  const char* name;
  const char* key;
  const char* printed;     // the viewer's line
  const char* renderArgs;  // what render takes for the same view
};

class ViewCliDebugView : public ViewCli, public ::testing::WithParamInterface<DebugViewCase> {};

TEST_P(ViewCliDebugView, MatchesRender) {
  SG_REQUIRE_ASSETS();
  const auto& c = GetParam();
  const fs::path viewed = dir_.path() / "viewed.png", rendered = dir_.path() / "rendered.png";
  const std::string frame = kMixedScene.string() + " --frame 0 --size 320x180 --bias 0";
  const fs::path record = dir_.path() / "record", shots = dir_.path() / "shots";
  const auto r = view(frame + " --record " + record.string() + " --screenshot-dir " + shots.string(),
                      std::string("key ") + c.key + "\nwait 2\nscreenshot " + viewed.string() + "\nkey P\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find(std::string("view: ") + c.printed), std::string::npos) << r.output;
  // --record wrote every frame shown, P the frame as the script's screenshot.
  const auto shown = r.output.find("viewer: ");
  ASSERT_NE(shown, std::string::npos) << r.output;
  const auto frames = size_t(std::atoi(r.output.c_str() + shown + 8));
  EXPECT_GT(frames, 2u);
  EXPECT_EQ(size_t(std::distance(fs::directory_iterator(record), fs::directory_iterator())), frames);
  EXPECT_EQ(differing(sg::image::readPng(shots / "screenshot-000.png"), sg::image::readPng(viewed), 0), 0u);
  const auto rr = sg::test::runCli("render " + frame + " " + c.renderArgs + " -o " + rendered.string());
  ASSERT_EQ(rr.exitCode, 0) << rr.output;
  const auto a = sg::image::readPng(viewed), b = sg::image::readPng(rendered);
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_EQ(differing(a, b, 2), 0u);
}

INSTANTIATE_TEST_SUITE_P(Views, ViewCliDebugView,
                         ::testing::Values(DebugViewCase{"Level", "2", "level", "--view level"},
                                           DebugViewCase{"UvChecker", "5", "uv checker", "--material debug-uv-checker"},
                                           DebugViewCase{"TriangleId", "6", "triangle id", "--material debug-triangle-id"}),
                         [](const ::testing::TestParamInfo<DebugViewCase>& p) { return std::string(p.param.name); });

// An effect toggled off leaves its pass out of the frame: under a shadowed
// sun the viewer's frame without shadows is render's of a frame file that
// removes them, and differs from the frame with them.
TEST_F(ViewCli, AnEffectToggledOffLeavesItsPassOut) {
  SG_REQUIRE_ASSETS();
  const std::string box = sg::test::samplePath("Box").string();
  const auto scene = dir_.write("shadowed.json", R"({"objects": [
    {"gltf": ")" + box + R"(", "name": "floor", "translation": [0, -0.6, 0], "scale": [6, 0.2, 6]},
    {"gltf": ")" + box + R"(", "name": "box", "translation": [0, 0.5, 0]}],
    "lights": [{"type": "directional", "direction": [-0.4, -1, -0.6], "intensity": 3, "shadows": true}],
    "cameraPaths": [{"name": "front", "type": "keys", "keys": [{"t": 0, "position": [0, 2, 5], "target": [0, 0, 0]}]}]})");
  const auto noShadows = dir_.write("no-shadows.json", R"({"name": "no-shadows", "base": "decoupled", "remove": ["shadows"]})");
  const fs::path on = dir_.path() / "on.png", off = dir_.path() / "off.png", rendered = dir_.path() / "rendered.png";
  const std::string frame = scene.string() + " --frame 0 --size 240x135 --bias 0";
  const auto r = view(frame, "wait 1\nscreenshot " + on.string() + "\neffect shadows off\nwait 1\nscreenshot " +
                                 off.string() + "\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("effect shadows: off"), std::string::npos) << r.output;
  const auto rr = sg::test::runCli("render " + frame + " --frame-graph " + noShadows.string() + " -o " + rendered.string());
  ASSERT_EQ(rr.exitCode, 0) << rr.output;
  const auto a = sg::image::readPng(on), b = sg::image::readPng(off), c = sg::image::readPng(rendered);
  ASSERT_EQ(b.width, c.width);
  EXPECT_EQ(differing(b, c, 2), 0u);
  EXPECT_GT(differing(a, b, 8), 100u) << "the box's shadow on the floor should be gone";
  const auto bad = view(frame, "effect sparkle off\n");
  EXPECT_EQ(bad.exitCode, 1);
  EXPECT_NE(bad.output.find(":1: effect 'sparkle': the frame has no such effect (it has: shadows, environment, bloom)"),
            std::string::npos)
      << bad.output;
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

// Minimizing pauses rendering: under a window manager the script iconifies
// the window and waits 10 idle waits; no frame is rendered (none recorded)
// until it is restored, and the frames after are render's image again.
TEST_F(ViewCli, MinimizingPausesRendering) {
  SG_REQUIRE_ASSETS();
  sg::test::TwmWindowManager wm;
  ASSERT_TRUE(wm.ok()) << wm.error();
  const fs::path record = dir_.path() / "record", after = dir_.path() / "after.png",
                 rendered = dir_.path() / "rendered.png";
  const std::string frame = kMixedScene.string() + " --frame 0 --size 240x135 --bias 0";
  const auto r = view(frame + " --record " + record.string(),
                      "wait 3\nminimize\nwait 10\nrestore\nwait 2\nscreenshot " + after.string() + "\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto number = [&](const std::string& text) {
    const auto at = r.output.find(text);
    return at == std::string::npos ? -1 : std::atoi(r.output.c_str() + at + text.size());
  };
  const int before = number("minimized after "), resumed = number("restored after ");
  ASSERT_GE(before, 3) << r.output;
  EXPECT_EQ(resumed, before) << "frames were rendered while minimized: " << r.output;
  EXPECT_GE(number("frames ("), 10) << "idle waits while minimized: " << r.output;
  const int shown = number("viewer: ");
  EXPECT_GT(shown, before) << r.output;
  EXPECT_EQ(size_t(std::distance(fs::directory_iterator(record), fs::directory_iterator())), size_t(shown));
  const auto rr = sg::test::runCli("render " + frame + " -o " + rendered.string());
  ASSERT_EQ(rr.exitCode, 0) << rr.output;
  const auto a = sg::image::readPng(after), b = sg::image::readPng(rendered);
  ASSERT_EQ(a.width, b.width);
  EXPECT_EQ(differing(a, b, 2), 0u);
}

// Without a window manager nothing can iconify the window: the script says so on its line.
TEST_F(ViewCli, MinimizeWithoutAWindowManagerNamesTheLine) {
  const auto r = view("--size 160x90", "wait 1\nminimize\nquit\n");
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(lines(r.output), 1u) << r.output;
  EXPECT_NE(r.output.find(":2: minimize: the window system did not iconify the window"), std::string::npos) << r.output;
}

// C steps through the scene's glTF cameras and camera paths back to the free
// camera (mixed.json: the engine's glTF camera, the path "orbit"); after an
// orbit, F frames the scene as render frames a scene without a camera
// (boxes.json; the same framing rebuilt from the controller's angles, so a few
// pixels may round differently).
TEST_F(ViewCli, CKeySelectsTheCameraPathAndFFramesTheScene) {
  SG_REQUIRE_ASSETS();
  const fs::path framed = dir_.path() / "framed.png", rendered = dir_.path() / "rendered.png";
  const auto cameras = view(kMixedScene.string() + " --size 160x90 --frame 0", "key C\nkey C\nkey C\nquit\n");
  ASSERT_EQ(cameras.exitCode, 0) << cameras.output;
  EXPECT_NE(cameras.output.find("camera: camera 0: \ncamera: path 0: orbit\ncamera: free\n"), std::string::npos)
      << cameras.output;
  const std::string frame = (fs::path(SG_SOURCE_DIR) / "tests/scenes/boxes.json").string() + " --size 320x180 --bias 0";
  const auto r = view(frame + " --frame 0", "mouse drag 160 90 220 60\nwait 1\nkey F\nwait 1\nscreenshot " +
                                              framed.string() + "\nquit\n");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("camera: free, framing the scene"), std::string::npos) << r.output;
  const auto rr = sg::test::runCli("render " + frame + " -o " + rendered.string());
  ASSERT_EQ(rr.exitCode, 0) << rr.output;
  const auto a = sg::image::readPng(framed), b = sg::image::readPng(rendered);
  ASSERT_EQ(a.width, b.width);
  EXPECT_LT(differing(a, b, 16), a.pixels.size() / 4 / 100) << "more than 1% of the pixels differ from render's framing";
}

}  // namespace
