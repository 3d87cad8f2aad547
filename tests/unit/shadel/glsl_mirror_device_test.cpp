// The GLSL twins of addressing and level selection, run on lavapipe, give
// the C++ functions' results: what shadel-mark, composite and layer-shade
// compute is what the CPU side and its tests assume.
#include "../../device/device_fixture.hpp"

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pipeline.hpp>

#include "glsl_mirror.hpp"

namespace sg::test {

// Without a level rule, and compiled as shadel-mark's and composite's
// variant for objects with one (shadel::levelRuleDefines): the
// unmipmapped-texture rule and one with more anisotropy and a bias.
TEST_F(DeviceTest, ShadelGlslMirrorsCpp) {
  library.addDirectory(SG_SOURCE_DIR);
  library.add(shadel::test::kMirrorShaderPath, shadel::test::kMirrorShader);
  constexpr uint32_t kCount = 50000;
  const std::vector<uint32_t> cases = shadel::test::makeMirrorCases(kCount, 2024);
  for (const shadel::LevelRule rule :
       {shadel::LevelRule{}, shadel::kUnmipmappedLevelRule, shadel::LevelRule{.maxAnisotropyLog2 = 2.25f, .bias = -0.25f}}) {
    SCOPED_TRACE("level rule k " + std::to_string(rule.maxAnisotropyLog2) + " bias " + std::to_string(rule.bias));
    gpu::Pipeline pipeline(*context, *compiler, *pipelineCache,
                           gpu::ComputePipelineDesc{.shader = {.path = shadel::test::kMirrorShaderPath, .defines = shadel::levelRuleDefines(rule)},
                                                    .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                                                            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                                                               .pushConstantBytes = 4}});
    gpu::Buffer in(*context, *memory,
                   {cases.size() * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Upload, "cases"});
    in.write(cases.data(), cases.size() * 4);
    gpu::Buffer out(*context, *memory,
                    {size_t{kCount} * shadel::test::kResultWords * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                     gpu::MemoryLocation::Readback, "results"});
    gpu::DescriptorArena descriptors(*context);
    context->submitAndWait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
      descriptors.bind(cmd, pipeline, {{0, gpu::BufferBinding{in.handle()}}, {1, gpu::BufferBinding{out.handle()}}});
      const uint32_t count = kCount;
      vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof count, &count);
      vkCmdDispatch(cmd, (kCount + 63) / 64, 1, 1);
      gpu::hostReadAfterCompute(cmd);
    });
    const std::string mismatch = shadel::test::compareMirrorResults(cases, out.view<uint32_t>().data(), kCount, rule);
    EXPECT_TRUE(mismatch.empty()) << mismatch;
  }
}

}  // namespace sg::test
