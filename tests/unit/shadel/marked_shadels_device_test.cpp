// layer-shade's marked-shadel packing (passes/layer-shade/marked_shadels.glsl),
// run on lavapipe: invocation i of n, walking a chunk's shadel mask as the
// generated layer-shade main does, must get exactly the marked shadels i,
// i + n, i + 2n, ... in order, so each marked shadel is shaded once; masks:
// empty, full, every single bit, one half only, and random; n = 8 (lavapipe)
// and 64 (a wave64 GPU).
#include <algorithm>
#include <glm/glm.hpp>
#include <random>
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <string>
#include <vector>

#include "../../device/device_fixture.hpp"

namespace sg::test {
namespace {

constexpr const char *kShaderPath = "tests/shadel/marked_shadels.comp";

// One invocation per mask and lane: results[mask * 64 + slot] = the texel the
// lane shades as its slot (slot = lane + k * lanes); 255 where none.
constexpr const char *kShader = R"(#version 460
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "passes/layer-shade/marked_shadels.glsl"
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Masks { uvec2 masks[]; };
layout(std430, set = 0, binding = 1) buffer Results { uint results[]; };
layout(push_constant) uniform Push { uint count; uint lanes; };

void main() {
  uint mask = gl_GlobalInvocationID.x / lanes, lane = gl_GlobalInvocationID.x % lanes;
  if (mask >= count) return;
  uint slot = lane;
  for (uint64_t left = sgSkipMarked(packUint2x32(masks[mask]), lane); left != 0ul; left = sgSkipMarked(left, lanes)) {
    results[mask * 64u + slot] = sgFirstMarkedTexel(left);
    slot += lanes;
  }
}
)";

class MarkedShadelsDeviceTest : public DeviceTest {
 protected:
  std::vector<uint32_t> run(const std::vector<glm::uvec2> &masks, uint32_t lanes) {
    gpu::Pipeline pipeline(*context, *compiler, *pipelineCache,
                           gpu::ComputePipelineDesc{.shader = {.path = kShaderPath},
                                                    .layout = {.bindings = {{0}, {1}}, .pushConstantBytes = 8}});
    gpu::Buffer in(
        *context, *memory,
        {masks.size() * sizeof(glm::uvec2), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Upload, "masks"});
    in.write(masks.data(), masks.size() * sizeof(glm::uvec2));
    gpu::Buffer out(*context, *memory,
                    {masks.size() * 64 * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                     gpu::MemoryLocation::Readback, "texels"});
    std::fill_n(out.view<uint32_t>().begin(), masks.size() * 64, 255u);
    gpu::DescriptorArena descriptors(*context);
    const uint32_t push[2] = {uint32_t(masks.size()), lanes};
    context->submitAndWait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
      descriptors.bind(cmd, pipeline, {{0, gpu::BufferBinding{in.handle()}}, {1, gpu::BufferBinding{out.handle()}}});
      vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, push);
      vkCmdDispatch(cmd, (push[0] * lanes + 63) / 64, 1, 1);
      VkMemoryBarrier2 host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
      host.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
      host.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
      host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
      host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
      VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
      dependency.memoryBarrierCount = 1;
      dependency.pMemoryBarriers = &host;
      vkCmdPipelineBarrier2(cmd, &dependency);
    });
    const auto view = out.view<uint32_t>();
    return {view.begin(), view.end()};
  }
};

TEST_F(MarkedShadelsDeviceTest, EachLaneGetsEveryNthMarkedShadelInOrder) {
  library.addDirectory(SG_SOURCE_DIR);
  library.add(kShaderPath, kShader);
  std::vector<uint64_t> masks{0, ~uint64_t(0), 0xFFFFFFFFull, 0xFFFFFFFF00000000ull, 0x8000000000000001ull};
  for (int bit = 0; bit < 64; ++bit) masks.push_back(uint64_t(1) << bit);
  std::mt19937_64 rng(14);
  for (int i = 0; i < 500; ++i) masks.push_back(rng() & rng());  // about a quarter of the bits
  for (int i = 0; i < 500; ++i) masks.push_back(rng() | rng());  // about three quarters
  std::vector<glm::uvec2> halves;
  for (const uint64_t m : masks) halves.emplace_back(uint32_t(m), uint32_t(m >> 32));
  for (const uint32_t lanes : {8u, 64u}) {
    SCOPED_TRACE(std::to_string(lanes) + " lanes");
    const std::vector<uint32_t> results = run(halves, lanes);
    size_t mismatches = 0;
    for (size_t i = 0; i < masks.size() && mismatches < 10; ++i) {
      std::vector<uint32_t> expected;
      for (uint32_t bit = 0; bit < 64; ++bit)
        if ((masks[i] >> bit) & 1u) expected.push_back(bit);
      expected.resize(64, 255u);
      const std::vector<uint32_t> got(results.begin() + std::ptrdiff_t(i * 64),
                                      results.begin() + std::ptrdiff_t(i * 64 + 64));
      if (got != expected) {
        ++mismatches;
        std::string slots;
        for (size_t n = 0; n < 64; ++n)
          if (got[n] != expected[n])
            slots += " slot " + std::to_string(n) + ": " + std::to_string(got[n]) + " not " +
                     std::to_string(expected[n]) + ";";
        ADD_FAILURE() << "mask 0x" << std::hex << masks[i] << std::dec << ":" << slots;
      }
    }
  }
}

}  // namespace
}  // namespace sg::test
