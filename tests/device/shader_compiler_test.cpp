#include "device_fixture.hpp"

namespace sg::test {
namespace {
const char* kCommon = "const uint kFill = 7u;\nuint twice(uint x) { return 2u * x; }\n";
const char* kFill = R"(#version 460
#include "common.glsl"
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) buffer Out { uint values[]; };
void main() { values[gl_GlobalInvocationID.x] = twice(gl_GlobalInvocationID.x) + kFill + EXTRA; }
)";
}  // namespace

TEST_F(DeviceTest, CompilesWithIncludeAndDefine) {
  library.add("test/common.glsl", kCommon);
  library.add("test/fill.comp", kFill);
  auto spirv = compiler->compile({.path = "test/fill.comp", .defines = {{"EXTRA", "1u"}}});
  ASSERT_GT(spirv.size(), 5u);
  EXPECT_EQ(spirv[0], 0x07230203u);  // SPIR-V magic
}

TEST_F(DeviceTest, CompileErrorReportsFileAndLine) {
  library.add("test/broken.comp", "#version 460\nlayout(local_size_x = 1) in;\n\nvoid main() {\n  undeclared = 1;\n}\n");
  try {
    compiler->compile({.path = "test/broken.comp"});
    FAIL() << "expected a ShaderCompileError";
  } catch (const gpu::ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "test/broken.comp");
    EXPECT_EQ(e.line(), 5);
    EXPECT_NE(std::string(e.what()).find("undeclared"), std::string::npos) << e.what();
  }
}

TEST_F(DeviceTest, CompileErrorInIncludedFileNamesThatFile) {
  library.add("test/bad.glsl", "// line 1\nfloat f() { return missing; }\n");
  library.add("test/uses_bad.comp", "#version 460\n#include \"bad.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
  try {
    compiler->compile({.path = "test/uses_bad.comp"});
    FAIL() << "expected a ShaderCompileError";
  } catch (const gpu::ShaderCompileError& e) {
    EXPECT_EQ(e.file(), "test/bad.glsl");
    EXPECT_EQ(e.line(), 2);
  }
}

TEST_F(DeviceTest, MissingIncludeIsAnError) {
  library.add("test/no_include.comp", "#version 460\n#include \"nowhere.glsl\"\nvoid main() {}\n");
  EXPECT_THROW(compiler->compile({.path = "test/no_include.comp"}), gpu::ShaderCompileError);
}

TEST_F(DeviceTest, SecondCompileIsServedFromDisk) {
  library.add("test/common.glsl", kCommon);
  library.add("test/fill.comp", kFill);
  gpu::ShaderRequest request{.path = "test/fill.comp", .defines = {{"EXTRA", "3u"}}};
  auto first = compiler->compile(request);
  EXPECT_EQ(compiler->stats().compiled, 1u);
  // A new compiler (a new process, in effect) with the same cache directory.
  gpu::ShaderCompiler second(library, cacheDir);
  auto again = second.compile(request);
  EXPECT_EQ(second.stats().compiled, 0u);
  EXPECT_EQ(second.stats().diskHits, 1u);
  EXPECT_EQ(first, again);
  // Changing an included file changes the key: compiled again, not served stale.
  library.add("test/common.glsl", std::string(kCommon) + "// edited\nconst uint kOther = 1u;\n");
  second.compile(request);
  EXPECT_EQ(second.stats().compiled, 1u);
}

}  // namespace sg::test
