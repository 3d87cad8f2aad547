// Frame descriptions resolved against a registry of passes that only declare
// their frame resources: no device, no graph.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <shadelgraph/plugin/frame_description.hpp>
#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugin {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

PassPlugin pass(std::string name, std::vector<std::string> reads, std::vector<std::string> writes,
                std::vector<PassParameter> parameters = {}) {
  return {.name = std::move(name), .reads = std::move(reads), .writes = std::move(writes),
          .parameters = std::move(parameters), .declare = [](render::FrameContext&) {}};
}

// depth -> shade -> tonemap, and an overlay that reads depth after tonemap.
Registry registry() {
  Registry r;
  r.addPass(pass("depth", {"view.draws"}, {"scene.depth"}));
  r.addPass(pass("shade", {"scene.depth"}, {"scene.hdr"}, {{"filter", 2, ""}, {"gain", 1.0, ""}, {"label", "x", ""}}));
  r.addPass(pass("tonemap", {"scene.hdr", "scene.ldr"}, {"scene.ldr"}));
  r.addPass(pass("overlay", {"scene.depth", "scene.ldr"}, {"scene.ldr"}));
  r.addPass(pass("ao", {"scene.depth"}, {"ao.image"}));
  r.addPass(pass("uses-ao", {"ao.image", "scene.hdr"}, {"scene.hdr"}));
  r.addFrame({.name = "basic", .passes = {{.pass = "depth"}, {.pass = "shade"}, {.pass = "tonemap"}}});
  return r;
}

std::vector<std::string> names(const ResolvedFrame& frame) {
  std::vector<std::string> n;
  for (const auto& p : frame.passes) n.push_back(p.pass->name);
  return n;
}

ResolvedFrame resolveJson(const Registry& r, const char* json) {
  return resolveFrame(parseFrameDescription(nlohmann::json::parse(json), "test.json"), r);
}

std::string errorOf(const Registry& r, const char* json) {
  try {
    resolveJson(r, json);
  } catch (const FrameError& e) {
    return e.what();
  }
  return "no error";
}

TEST(FrameDescription, ARegisteredFrameRunsItsPassesInListOrder) {
  const auto r = registry();
  EXPECT_THAT(names(resolveFrame(r.frame("basic"), r)), ElementsAre("depth", "shade", "tonemap"));
}

TEST(FrameDescription, AFileAddsAPassAfterTheBasesLastOne) {
  const auto r = registry();
  const auto frame = resolveJson(r, R"({"name": "mine", "base": "basic", "passes": ["overlay"]})");
  EXPECT_EQ(frame.name, "mine");
  EXPECT_THAT(names(frame), ElementsAre("depth", "shade", "tonemap", "overlay"));
}

TEST(FrameDescription, BeforeAndAfterPlaceAPassBetweenTheBasesPasses) {
  const auto r = registry();
  const auto frame = resolveJson(r, R"({"base": "basic", "passes": [
      {"pass": "uses-ao", "before": "tonemap", "after": "shade"}, {"pass": "ao", "after": "depth"}]})");
  // ao goes right after what it follows; uses-ao (it reads ao.image, which
  // only ao writes) waits until just before tonemap.
  EXPECT_THAT(names(frame), ElementsAre("depth", "ao", "shade", "uses-ao", "tonemap"));
}

TEST(FrameDescription, APassAfterAnotherGoesRightAfterItNotAtTheEnd) {
  const auto r = registry();
  const auto frame = resolveJson(r, R"({"base": "basic", "passes": [{"pass": "ao", "after": "depth"}]})");
  EXPECT_THAT(names(frame), ElementsAre("depth", "ao", "shade", "tonemap"));
}

TEST(FrameDescription, RemoveAndReplaceEditTheBase) {
  const auto r = registry();
  EXPECT_THAT(names(resolveJson(r, R"({"base": "basic", "replace": {"tonemap": "overlay"}, "passes": [
      {"pass": "tonemap", "before": "overlay"}]})")),
              ElementsAre("depth", "shade", "tonemap", "overlay"));
  EXPECT_THAT(errorOf(r, R"({"base": "basic", "remove": ["shade"]})"),
              AllOf(HasSubstr("pass 'tonemap' reads 'scene.hdr'"), HasSubstr("no pass of the frame writes")));
}

TEST(FrameDescription, ParametersMergeOverDefaultsAndKeepTheirTypes) {
  const auto r = registry();
  const auto frame = resolveJson(r, R"({"base": "basic", "parameters": {"shade": {"filter": 0, "gain": 3}}})");
  EXPECT_EQ(frame.passes[1].parameters["filter"], 0);
  EXPECT_EQ(frame.passes[1].parameters["gain"], 3);
  EXPECT_EQ(frame.passes[1].parameters["label"], "x") << "defaults stay";
  EXPECT_THAT(errorOf(r, R"({"base": "basic", "parameters": {"shade": {"filter": 0.5}}})"),
              HasSubstr("parameter 'filter' must be an integer"));
  EXPECT_THAT(errorOf(r, R"({"base": "basic", "parameters": {"shade": {"label": 3}}})"),
              HasSubstr("parameter 'label' must be a string"));
  EXPECT_THAT(errorOf(r, R"({"base": "basic", "parameters": {"shade": {"sharpness": 1}}})"),
              AllOf(HasSubstr("has no parameter 'sharpness'"), HasSubstr("filter, gain, label")));
  EXPECT_THAT(errorOf(r, R"({"base": "basic", "parameters": {"overlay": {}}})"),
              HasSubstr("parameters for 'overlay', which the frame does not run"));
}

// The three failures the user must get in one line naming pass and resource.
TEST(FrameDescription, AReadOfAResourceNobodyWritesNamesThePassAndTheResource) {
  const auto r = registry();
  EXPECT_EQ(errorOf(r, R"({"name": "f", "passes": ["depth", "uses-ao", "shade", "tonemap"]})"),
            "frame 'f' (test.json): pass 'uses-ao' reads 'ao.image', which no pass of the frame writes");
  EXPECT_EQ(errorOf(r, R"({"name": "f", "passes": ["depth", "uses-ao", "ao", "shade", "tonemap"]})"),
            "frame 'f' (test.json): pass 'uses-ao' reads 'ao.image', which only 'ao' writes, after it");
}

TEST(FrameDescription, AnUnknownPassIsNamedWithTheRegisteredOnes) {
  const auto r = registry();
  EXPECT_THAT(errorOf(r, R"({"name": "f", "base": "basic", "passes": ["bloom"]})"),
              AllOf(HasSubstr("frame 'f' (test.json): unknown pass 'bloom'"), HasSubstr("ao, depth, overlay")));
  EXPECT_THAT(errorOf(r, R"({"base": "cinematic"})"), HasSubstr("base frame 'cinematic' is not registered"));
  EXPECT_THAT(errorOf(r, R"({"base": "basic", "passes": [{"pass": "ao", "after": "bloom"}]})"),
              HasSubstr("pass 'ao' is after 'bloom', which the frame does not run"));
}

TEST(FrameDescription, ConstraintsThatCycleAreAnError) {
  const auto r = registry();
  EXPECT_EQ(errorOf(r, R"({"name": "f", "base": "basic", "passes": [{"pass": "ao", "after": "uses-ao"},
      {"pass": "uses-ao", "after": "ao"}]})"),
            "frame 'f' (test.json): after/before constraints (and the resources they read) form a cycle among "
            "passes ao, uses-ao");
  // A constrained reader goes after the one writer of what it reads, which here contradicts its constraint.
  EXPECT_THAT(errorOf(r, R"({"name": "f", "base": "basic", "passes": [{"pass": "ao", "after": "tonemap"},
      {"pass": "uses-ao", "before": "tonemap"}]})"),
              HasSubstr("form a cycle among passes"));
}

TEST(FrameDescription, MalformedFilesNameTheField) {
  const auto r = registry();
  EXPECT_THAT(errorOf(r, R"({"passes": [{"name": "x"}]})"), HasSubstr("passes[0]: unknown field 'name'"));
  EXPECT_THAT(errorOf(r, R"({"passes": [7]})"), HasSubstr("passes[0]: expected a pass name"));
  EXPECT_THAT(errorOf(r, R"({"base": "basic", "passes": ["shade"]})"), HasSubstr("pass 'shade' appears twice"));
  EXPECT_THAT(errorOf(r, R"([1, 2])"), HasSubstr("expected a JSON object"));
}

TEST(FrameDescription, ResolvedFrameTellsWhichRendererResourcesItReads) {
  const auto r = registry();
  const auto frame = resolveFrame(r.frame("basic"), r);
  EXPECT_TRUE(frame.reads("view.draws"));
  EXPECT_FALSE(frame.reads("view.decoupled"));
}

}  // namespace
}  // namespace sg::plugin
