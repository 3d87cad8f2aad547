// The GLSL twins compile (glslang only, no device): the device test runs them.
#include <gtest/gtest.h>

#include <shadelgraph/gpu/shader_compiler.hpp>

#include "glsl_mirror.hpp"

namespace sg::shadel {
namespace {

TEST(ShadelGlsl, AddressAndLevelShadersCompile) {
  gpu::ShaderLibrary library;
  library.addDirectory(SG_SOURCE_DIR);
  library.add(test::kMirrorShaderPath, test::kMirrorShader);
  gpu::ShaderCompiler compiler(library, std::filesystem::path());
  try {
    const std::vector<uint32_t> spirv = compiler.compile({.path = test::kMirrorShaderPath});
    EXPECT_GT(spirv.size(), 100u);
  } catch (const gpu::ShaderCompileError& error) {
    FAIL() << error.log();
  }
  // Each header on its own, included twice (the include guards hold).
  for (const char* header : {"framework/shadel/shaders/shadel_address.glsl", "framework/shadel/shaders/shadel_level.glsl"}) {
    const std::string source = std::string("#version 460\n#include \"") + header + "\"\n#include \"" + header +
                               "\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
    EXPECT_NO_THROW(compiler.compile({.path = "tests/shadel/include_twice.comp", .source = source})) << header;
  }
}

}  // namespace
}  // namespace sg::shadel
