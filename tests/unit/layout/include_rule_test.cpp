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

TEST(IncludeRule, EveryIncludeKeepsToTheFloors) {
  const std::filesystem::path root = SG_SOURCE_DIR;
  const LayoutReport report = checkLayout(root);
  // The scan read the tree (a wrong root would pass vacuously).
  ASSERT_GT(report.files, 100u) << "sources under " << root;
  ASSERT_GT(report.projectIncludes, 300u) << "project includes resolved under " << root;

  std::ostringstream violations;
  for (const Violation& v : report.violations) violations << "  " << v.message() << "\n";
  std::ostringstream unresolved;
  for (const Include& i : report.unresolved)
    unresolved << "  " << i.file << ":" << i.line << " includes " << i.written()
               << ", which resolves to no file (a new include root? add it to kIncludeRoots in include_scan.cpp)\n";

  EXPECT_TRUE(violations.str().empty())
      << "layer rule violations (framework <- materials, passes <- plugins <- apps):\n" << violations.str();
  EXPECT_TRUE(unresolved.str().empty()) << unresolved.str();
  std::printf("%zu files, %zu project includes, %zu violations\n", report.files, report.projectIncludes,
              report.violations.size());
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
