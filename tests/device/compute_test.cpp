#include "device_fixture.hpp"

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pipeline.hpp>

namespace sg::test {

TEST_F(DeviceTest, ComputeDispatchFillsBuffer) {
  library.add("test/fill.comp", R"(#version 460
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) buffer Out { uint values[]; };
layout(push_constant) uniform Push { uint count; uint scale; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < count) values[i] = i * scale + 1u;
}
)");
  constexpr uint32_t kCount = 1000, kScale = 3;
  gpu::Pipeline pipeline(*context, *compiler, *pipelineCache,
                         gpu::ComputePipelineDesc{.shader = {.path = "test/fill.comp"},
                                                  .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                                                             .pushConstantBytes = 8}});
  gpu::Buffer out(*context, *memory,
                  {kCount * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Readback, "out"});
  std::fill_n(out.view<uint32_t>().data(), kCount, 0xdeadbeefu);
  gpu::DescriptorArena descriptors(*context);
  context->submitAndWait([&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
    descriptors.bind(cmd, pipeline, {{0, gpu::BufferBinding{out.handle()}}});
    uint32_t push[2] = {kCount, kScale};
    vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, push);
    vkCmdDispatch(cmd, (kCount + 63) / 64, 1, 1);
    gpu::hostReadAfterCompute(cmd);
  });
  auto values = out.view<uint32_t>();
  for (uint32_t i = 0; i < kCount; ++i) ASSERT_EQ(values[i], i * kScale + 1) << "at element " << i;
}

}  // namespace sg::test
