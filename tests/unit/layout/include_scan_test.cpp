// The include scanner on a small made-up tree: it sees every include form the
// project uses, resolves each the way the build does, and judges the floors.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "include_scan.hpp"
#include "test_support.hpp"

namespace sg::test::layout {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

std::vector<std::string> messages(const LayoutReport& report) {
  std::vector<std::string> out;
  for (const Violation& v : report.violations) out.push_back(v.message());
  return out;
}

class IncludeScan : public ::testing::Test {
 protected:
  void SetUp() override {
    dir.write("framework/graph/pass.hpp", "#pragma once\n");
    dir.write("framework/render/shaders/frame.glsl", "// frame\n");
    dir.write("passes/forward/forward.hpp", "#pragma once\n");
    dir.write("passes/forward/forward.frag", "#include <framework/render/shaders/frame.glsl>\n");
    dir.write("passes/builtin_shaders.hpp", "#pragma once\n");
    dir.write("materials/gltf-pbr/surface.glsl", "// surface\n");
    dir.write("plugins/decoupled/shaders/decoupled.glsl", "// decoupled\n");
    dir.write("plugins/forward/forward_recipe.hpp", "#include \"forward/forward.hpp\"\n");
    dir.write("apps/tool/main.cpp", "#include <forward/forward_recipe.hpp>\n#include <builtin_shaders.hpp>\n");
  }
  TempDir dir;
};

TEST_F(IncludeScan, AllowedIncludesPass) {
  dir.write("framework/graph/pass.cpp",
            "#include <shadelgraph/graph/pass.hpp>\n#include \"pass.hpp\"\n#include <vector>\n#include <glm/glm.hpp>\n");
  const LayoutReport report = checkLayout(dir.path());
  EXPECT_THAT(messages(report), IsEmpty());
  EXPECT_THAT(report.unresolved, IsEmpty());
  EXPECT_EQ(report.files, 10u);
  // pass.hpp twice, frame.glsl, forward.hpp, forward_recipe.hpp, builtin_shaders.hpp; <vector>, <glm> are not ours.
  EXPECT_EQ(report.projectIncludes, 6u);
}

TEST_F(IncludeScan, QuotedIncludeThroughAnIncludeRootIsAPass) {
  dir.write("framework/graph/pass.cpp", "#include <vector>\n#include \"forward/forward.hpp\"\n");
  EXPECT_THAT(messages(checkLayout(dir.path())),
              ElementsAre("framework/graph/pass.cpp:2 includes \"forward/forward.hpp\" "
                          "(floor framework may not include floor passes)"));
}

TEST_F(IncludeScan, GlslIncludeOfAPluginFromAPassIsAViolation) {
  dir.write("passes/forward/forward.vert", "#version 460\n  #  include <plugins/decoupled/shaders/decoupled.glsl>\n");
  EXPECT_THAT(messages(checkLayout(dir.path())),
              ElementsAre("passes/forward/forward.vert:2 includes <plugins/decoupled/shaders/decoupled.glsl> "
                          "(floor passes may not include floor plugins)"));
}

TEST_F(IncludeScan, GeneratedGlslInACppStringLiteralCounts) {
  dir.write("framework/render/variants.cpp",
            "out << \"#version 460\\n\"\n"
            "    << \"#include <passes/forward/forward.frag>\\n\";\n"
            "out << \"#include <\" << layer.source << \">\\n\";\n"  // a computed path: nothing to resolve
            "const char* k = \"x\\n#include \\\"materials/gltf-pbr/surface.glsl\\\"\\n\";\n");
  EXPECT_THAT(messages(checkLayout(dir.path())),
              ElementsAre("framework/render/variants.cpp:2 includes <passes/forward/forward.frag> "
                          "(floor framework may not include floor passes)",
                          "framework/render/variants.cpp:4 includes \"materials/gltf-pbr/surface.glsl\" "
                          "(floor framework may not include floor materials)"));
}

TEST_F(IncludeScan, SiblingFloorsMayNotIncludeEachOther) {
  dir.write("materials/gltf-pbr/material.glsl", "#include \"surface.glsl\"\n#include <passes/forward/forward.frag>\n");
  EXPECT_THAT(messages(checkLayout(dir.path())),
              ElementsAre("materials/gltf-pbr/material.glsl:2 includes <passes/forward/forward.frag> "
                          "(floor materials may not include floor passes)"));
}

TEST_F(IncludeScan, RelativeIncludeThatClimbsIntoAnotherFloorIsJudgedByWhereItLands) {
  dir.write("framework/render/x.cpp", "#include \"../../plugins/forward/forward_recipe.hpp\"\n");
  EXPECT_THAT(messages(checkLayout(dir.path())),
              ElementsAre("framework/render/x.cpp:1 includes \"../../plugins/forward/forward_recipe.hpp\" "
                          "(floor framework may not include floor plugins)"));
}

TEST_F(IncludeScan, ProjectIncludeThatResolvesToNothingIsReported) {
  dir.write("framework/graph/pass.cpp", "#include \"gone.hpp\"\n#include <forward/gone.hpp>\n#include <CLI/CLI.hpp>\n");
  const LayoutReport report = checkLayout(dir.path());
  ASSERT_EQ(report.unresolved.size(), 2u);
  EXPECT_EQ(report.unresolved[0].written(), "\"gone.hpp\"");
  EXPECT_EQ(report.unresolved[1].written(), "<forward/gone.hpp>");
}

TEST_F(IncludeScan, CommentsAndPlainTextAreNotIncludes) {
  dir.write("framework/graph/pass.cpp", "// the variant #includes it\nint includeCount = 0;  // #include nothing\n");
  EXPECT_EQ(checkLayout(dir.path()).projectIncludes, 4u);  // the made-up tree's own four
}

// The material SDK check: the umbrella's closure, and example plugins' GLSL
// that includes the SDK, its own folder, or (listed) anything else.
TEST_F(IncludeScan, ExamplePluginGlslMayIncludeOnlyTheSdkAndItself) {
  dir.write("framework/plugin/shaders/material.glsl",
            "#include <framework/render/shaders/frame.glsl>\n#include \"surface.glsl\"\n");
  dir.write("framework/plugin/shaders/surface.glsl", "// Surface\n");
  dir.write("materials/gltf-pbr/brdf.glsl", "// brdf\n");
  dir.write("plugins/example-a/shaders/example-a/a.glsl",
            "#include <framework/plugin/shaders/material.glsl>\n#include \"helper.glsl\"\n"
            "#include <framework/render/shaders/frame.glsl>\n");
  dir.write("plugins/example-a/shaders/example-a/helper.glsl", "// its own\n");
  dir.write("plugins/example-b/shaders/b.frag",
            "#include <materials/gltf-pbr/brdf.glsl>\n#include <passes/builtin_shaders.hpp>\n#include \"gone.glsl\"\n");
  dir.write("plugins/example-b/b.cpp", "#include <materials/gltf-pbr/brdf.glsl>\n");  // C++: not judged here
  const SdkReport report = checkExampleSdkIncludes(dir.path());
  EXPECT_EQ(report.sdk, (std::set<std::string>{"framework/plugin/shaders/material.glsl",
                                               "framework/plugin/shaders/surface.glsl",
                                               "framework/render/shaders/frame.glsl"}));
  EXPECT_EQ(report.exampleGlslFiles, 3u);
  EXPECT_EQ(report.checked, 6u);
  ASSERT_EQ(report.outside.size(), 3u);
  EXPECT_EQ(report.outside[0],
            "plugins/example-b/shaders/b.frag:1 includes <materials/gltf-pbr/brdf.glsl> "
            "(materials/gltf-pbr/brdf.glsl is not in the material SDK: include <framework/plugin/shaders/material.glsl> only)");
  EXPECT_EQ(report.outside[2].rfind("plugins/example-b/shaders/b.frag:3 includes \"gone.glsl\" (resolves to no file", 0), 0u);
}

}  // namespace
}  // namespace sg::test::layout
