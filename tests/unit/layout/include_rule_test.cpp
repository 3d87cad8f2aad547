// The layer rule on the real source tree (DESIGN.md, "Layout"):
//   framework  <-  materials, passes  <-  plugins  <-  apps
// each folder includes only itself and floors strictly below it, in C++ and
// GLSL alike. materials and passes share a floor as siblings and include
// neither each other: a pass must serve any material and a material any
// frame; what both need (Surface, lights, debug colours) belongs to the
// framework's material SDK.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "include_scan.hpp"

namespace sg::test::layout {
namespace {

struct KnownViolation {
  const char* file;
  const char* include;  // as written, <x> or "x"
};

// Today's violations, every one. This list must only shrink, to empty: the
// frame/plugin redesign (issue 12) moves these files where they belong. The
// test fails on any violation missing here AND on any entry that no longer
// occurs, so fixing one means deleting its line.
const KnownViolation kKnownViolations[] = {
    // The generated material variants include a pass's GLSL.
    {"framework/render/material_variants.cpp", "<passes/layer-shade/shadel_context.glsl>"},
    {"framework/render/material_variants.cpp", "<passes/forward/forward_surface.glsl>"},
    // Passes include the decoupled plugin's bindings.
    {"passes/composite/composite.frag", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/composite/composite.vert", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/debug-views/occupancy.frag", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/layer-shade/shadel_context.glsl", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/layer-shade/shadel_context.glsl", "<plugins/decoupled/shaders/work.glsl>"},
    {"passes/shadel-allocate/shadel_allocate.comp", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/shadel-allocate/shadel_allocate.comp", "<plugins/decoupled/shaders/work.glsl>"},
    {"passes/shadel-clear/shadel_clear.comp", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/shadel-clear/shadel_clear.comp", "<plugins/decoupled/shaders/work.glsl>"},
    {"passes/shadel-mark/shadel_mark.frag", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/shadel-mark/shadel_mark.vert", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/support-expand/support_expand.comp", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/work-aggregate/work_fill.comp", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/work-aggregate/work_fill.comp", "<plugins/decoupled/shaders/work.glsl>"},
    {"passes/work-aggregate/work_offsets.comp", "<plugins/decoupled/shaders/decoupled.glsl>"},
    {"passes/work-aggregate/work_offsets.comp", "<plugins/decoupled/shaders/work.glsl>"},
};

TEST(IncludeRule, EveryIncludeKeepsToTheFloors) {
  const std::filesystem::path root = SG_SOURCE_DIR;
  const LayoutReport report = checkLayout(root);
  // The scan read the tree (a wrong root would pass vacuously).
  ASSERT_GT(report.files, 100u) << "sources under " << root;
  ASSERT_GT(report.projectIncludes, 300u) << "project includes resolved under " << root;

  std::set<std::pair<std::string, std::string>> known, seen;
  for (const KnownViolation& k : kKnownViolations) known.insert({k.file, k.include});
  std::ostringstream fresh;
  for (const Violation& v : report.violations) {
    seen.insert({v.include.file, v.include.written()});
    if (!known.count({v.include.file, v.include.written()})) fresh << "  " << v.message() << "\n";
  }
  std::ostringstream stale;
  for (const auto& [file, include] : known)
    if (!seen.count({file, include}))
      stale << "  " << file << " includes " << include << " no longer: delete its line from kKnownViolations\n";
  std::ostringstream unresolved;
  for (const Include& i : report.unresolved)
    unresolved << "  " << i.file << ":" << i.line << " includes " << i.written()
               << ", which resolves to no file (a new include root? add it to kIncludeRoots in include_scan.cpp)\n";

  EXPECT_TRUE(fresh.str().empty()) << "layer rule violations (framework <- materials, passes <- plugins <- apps):\n"
                                   << fresh.str();
  EXPECT_TRUE(stale.str().empty()) << "stale known violations:\n" << stale.str();
  EXPECT_TRUE(unresolved.str().empty()) << unresolved.str();
  std::printf("%zu files, %zu project includes, %zu violations (%zu known)\n", report.files, report.projectIncludes,
              report.violations.size(), known.size());
}

// The example plugins show a third party what to include: the material SDK
// (framework/plugin/shaders/material.glsl) and nothing else of shadelgraph's,
// neither a built-in material (materials/) nor a pass (passes/) nor any other
// framework file. Every include in their GLSL resolves into the SDK (the
// umbrella and what it includes) or into the plugin's own folder.
TEST(IncludeRule, ExamplePluginsIncludeOnlyTheMaterialSdk) {
  const std::filesystem::path root = SG_SOURCE_DIR;
  const SdkReport report = checkExampleSdkIncludes(root);
  // The SDK is there and holds what the issue names: Surface, lights, frame uniforms, sampling.
  ASSERT_TRUE(report.sdk.count(kSdkUmbrella)) << kSdkUmbrella << " is missing under " << root;
  for (const char* file : {"framework/plugin/shaders/surface.glsl", "framework/plugin/shaders/lights.glsl",
                           "framework/plugin/shaders/scene_material.glsl", "framework/render/shaders/frame.glsl"})
    EXPECT_TRUE(report.sdk.count(file)) << kSdkUmbrella << " does not include " << file;
  // The SDK is the framework's own: it includes nothing from materials/, passes/ or plugins/.
  for (const std::string& file : report.sdk)
    EXPECT_EQ(file.rfind("framework/", 0), 0u) << "the SDK includes " << file << ", outside framework/";
  // The scan saw the examples' GLSL (stripes, ssao: three files, each includes the SDK).
  ASSERT_GE(report.exampleGlslFiles, 3u);
  ASSERT_GE(report.checked, 3u);
  std::ostringstream outside;
  for (const std::string& o : report.outside) outside << "  " << o << "\n";
  EXPECT_TRUE(report.outside.empty()) << "example plugins including more than the material SDK:\n" << outside.str();
}

}  // namespace
}  // namespace sg::test::layout
