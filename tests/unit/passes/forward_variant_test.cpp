// What the forward variants of gltf-pbr compile to (glslang, no device):
// lavapipe runs both sides of every branch, so code a draw never takes still
// costs it every pixel. Only an alpha-mask draw's variant discards (a discard
// compiled in also defers lavapipe's depth write).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include <builtin_materials.hpp>
#include <builtin_shaders.hpp>
#include <forward/forward_material.hpp>
#include <shadelgraph/gpu/shader_compiler.hpp>

namespace sg::test {
namespace {

// Instructions of a SPIR-V module with these opcodes.
size_t countOps(const std::vector<uint32_t>& spirv, std::initializer_list<uint32_t> opcodes) {
  size_t count = 0;
  for (size_t i = 5; i < spirv.size();) {  // after the 5-word header
    const uint32_t words = spirv[i] >> 16, opcode = spirv[i] & 0xffffu;
    for (uint32_t op : opcodes) count += opcode == op;
    i += words ? words : 1;
  }
  return count;
}

// OpKill, OpTerminateInvocation, OpDemoteToHelperInvocation.
constexpr std::initializer_list<uint32_t> kDiscards{252, 4416, 5380};

class ForwardVariant : public ::testing::Test {
 protected:
  ForwardVariant() {
    library_.add(gpu::builtinShaders());
    materials::registerBuiltinMaterials(registry_);
  }
  std::vector<uint32_t> fragment(bool plain, bool alphaTest) {
    const passes::ForwardFrameFeatures frame{false, false, false};
    return compiler_.compile(
        passes::forwardMaterialPipeline(registry_, registry_.material("gltf-pbr"), false, plain, frame, alphaTest).fragment);
  }
  gpu::ShaderLibrary library_;
  gpu::ShaderCompiler compiler_{library_, {}};
  plugin::Registry registry_;
};

TEST_F(ForwardVariant, OnlyTheAlphaTestVariantDiscards) {
  EXPECT_EQ(countOps(fragment(false, false), kDiscards), 0u);
  EXPECT_EQ(countOps(fragment(true, false), kDiscards), 0u);
  EXPECT_GT(countOps(fragment(false, true), kDiscards), 0u);
  EXPECT_GT(countOps(fragment(true, true), kDiscards), 0u);
}

}  // namespace
}  // namespace sg::test
