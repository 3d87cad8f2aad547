// passes/support-expand/support_expand.comp on lavapipe (validation and
// synchronization validation on) against shadel::expandSupport: both
// dispatches with the pass's barrier between them, over real shadel spaces
// (ShadelSpace + buildGpuTables) with random marks, random supportChunks
// (0, 1, 2) and some level rectangles shrunk to sizes that are not multiples
// of 8 or smaller than a chunk, and radii up to the 8 chunks the shader
// reaches (an entry's side). One case has more than 65535 owned entries.
#include "../../device/device_fixture.hpp"

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include <decoupled/decoupled_tables.hpp>
#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/shadel/shadel_gpu_tables.hpp>
#include <shadelgraph/shadel/shadel_space.hpp>
#include <shadelgraph/shadel/support_expand.hpp>

namespace sg::test {
namespace {

constexpr const char* kShader = "passes/support-expand/support_expand.comp";
using shader::kBindSupportMasks;
using shader::kBindEntryBlocks;

struct Case {
  shadel::ShadelGpuTables tables;
  std::vector<uint32_t> supportChunks;  // by instance id
  std::vector<shadel::RemapEntry> remap;
  uint32_t entriesPerSideLog2 = 0;
};

Case makeCase(uint32_t seed, std::vector<uint32_t> level0Sizes) {
  std::mt19937 rng(seed);
  shadel::ShadelSpace space;  // 64K^2: a 16 MiB dense remap table
  Case c;
  for (uint32_t id = 0; id < level0Sizes.size(); ++id) {
    EXPECT_TRUE(space.allocate(id, shadel::makeDetailLevels(level0Sizes[id])).ok());
    const uint32_t radii[] = {0, 1, 1, 2, 3, 8};
    c.supportChunks.push_back(radii[rng() % 6]);
  }
  c.tables = shadel::buildGpuTables(space);
  c.entriesPerSideLog2 = space.geometry().entriesPerSideLog2();
  // Some levels use less than their square: sizes not a multiple of 8, below a chunk.
  for (auto& rect : c.tables.levelRects)
    if (rng() % 3 == 0) rect.size = std::max(1u, rect.size - uint32_t(rng() % std::min(rect.size, 70u)));
  c.remap.resize(space.geometry().entryCount());
  for (const auto& owned : c.tables.ownedEntries) {
    shadel::RemapEntry& entry = c.remap[owned.entryIndex];
    entry.objectInstanceId = owned.instanceId;
    const uint32_t marks = rng() % 3 == 0 ? 0 : rng() % 6;  // sparse: growth shows; a third empty
    for (uint32_t i = 0; i < marks; ++i) entry.occupancy |= uint64_t(1) << (rng() % 64);
  }
  return c;
}

class SupportExpandDeviceTest : public DeviceTest {
 protected:
  void SetUp() override {
    DeviceTest::SetUp();
    library.addDirectory(SG_SOURCE_DIR);
  }
  gpu::Buffer upload(const void* data, size_t bytes, VkBufferUsageFlags usage, const char* name) {
    gpu::Buffer buffer(*context, *memory, {std::max<size_t>(bytes, 16), usage, gpu::MemoryLocation::Upload, name});
    if (bytes) buffer.write(data, bytes);
    return buffer;
  }
  template <class T>
  gpu::Buffer storage(const std::vector<T>& data, const char* name) {
    return upload(data.data(), data.size() * sizeof(T), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, name);
  }

  // Runs the two dispatches the pass records; returns the remap table after
  // and sets `supportCounter` to counters.supportChunks.
  std::vector<shadel::RemapEntry> run(const Case& c, uint32_t& supportCounter) {
    const gpu::PipelineLayoutDesc layout{.bindings = {{1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                                      {2},
                                                      {3},
                                                      {4},
                                                      {5},
                                                      {6},
                                                      {7},
                                                      {kBindSupportMasks},
                                                      {kBindEntryBlocks}},
                                         .pushConstantBytes = sizeof(shader::SgEntrySpan)};
    gpu::Pipeline gather(*context, *compiler, *pipelineCache,
                         gpu::ComputePipelineDesc{.shader = {.path = kShader}, .layout = layout});
    gpu::Pipeline apply(*context, *compiler, *pipelineCache,
                        gpu::ComputePipelineDesc{.shader = {.path = kShader, .defines = {{"SG_SUPPORT_APPLY", "1"}}},
                                                 .layout = layout});
    const auto ownedCount = uint32_t(c.tables.ownedEntries.size());
    const auto objectCount = uint32_t(c.supportChunks.size());
    plugins::DecoupledParams params{};
    params.entriesPerSideLog2 = c.entriesPerSideLog2;
    params.ownedEntryCount = ownedCount;
    params.objectCount = objectCount;
    std::vector<plugins::DecoupledObject> objects(objectCount);
    for (uint32_t i = 0; i < objectCount; ++i) objects[i].supportChunks = c.supportChunks[i];
    plugins::ShadeCounters counters{};

    gpu::Buffer paramsBuffer = upload(&params, sizeof params, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "params");
    gpu::Buffer objectsBuffer = storage(objects, "objects");
    gpu::Buffer instancesBuffer = storage(c.tables.instances, "instances");
    gpu::Buffer rectsBuffer = storage(c.tables.levelRects, "level rects");
    gpu::Buffer ownedBuffer = storage(c.tables.ownedEntries, "owned entries");
    gpu::Buffer remap(*context, *memory,
                      {c.remap.size() * sizeof(shadel::RemapEntry), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       gpu::MemoryLocation::Readback, "remap"});
    remap.write(c.remap.data(), c.remap.size() * sizeof(shadel::RemapEntry));
    gpu::Buffer countersBuffer(*context, *memory,
                               {sizeof counters, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Readback,
                                "counters"});
    countersBuffer.write(&counters, sizeof counters);
    gpu::Buffer masks(*context, *memory,
                      {8ull * std::max(ownedCount, 1u), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Device,
                       "support masks"});

    const std::vector<gpu::DescriptorWrite> writes{
        {1, gpu::BufferBinding{paramsBuffer.handle()}},   {2, gpu::BufferBinding{objectsBuffer.handle()}},
        {3, gpu::BufferBinding{instancesBuffer.handle()}}, {4, gpu::BufferBinding{rectsBuffer.handle()}},
        {5, gpu::BufferBinding{remap.handle()}},          {6, gpu::BufferBinding{ownedBuffer.handle()}},
        {7, gpu::BufferBinding{countersBuffer.handle()}}, {kBindSupportMasks, gpu::BufferBinding{masks.handle()}},
        // Not read: the spans are pushed (SgEntrySpan.blocks 0).
        {kBindEntryBlocks, gpu::BufferBinding{masks.handle()}}};
    gpu::DescriptorArena descriptors(*context);
    // As the pass does over one span of every owned entry (passes::dispatchEntrySpans).
    const shader::SgEntrySpan span{0, ownedCount, 0};
    auto dispatchGroups = [&span](VkCommandBuffer cmd, const gpu::Pipeline& pipeline, uint32_t groups) {
      const uint32_t x = std::min(groups, 65535u);
      vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof span, &span);
      vkCmdDispatch(cmd, x, (groups + x - 1) / x, 1);
    };
    // The pass's barrier: the masks from gather to apply, gather's remap reads before apply's writes.
    auto gatherToApply = [](VkCommandBuffer cmd) {
      gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                         {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    };
    context->submitAndWait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, gather.handle());
      descriptors.bind(cmd, gather, writes);
      dispatchGroups(cmd, gather, (ownedCount + 63) / 64);
      gatherToApply(cmd);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, apply.handle());
      descriptors.bind(cmd, apply, writes);
      dispatchGroups(cmd, apply, (ownedCount + 63) / 64);
      gpu::hostReadAfterCompute(cmd);
    });
    plugins::ShadeCounters after{};
    std::memcpy(&after, countersBuffer.mapped(), sizeof after);
    supportCounter = after.supportChunks;
    std::vector<shadel::RemapEntry> result(c.remap.size());
    std::memcpy(result.data(), remap.mapped(), result.size() * sizeof(shadel::RemapEntry));
    return result;
  }

  void expectMatchesReference(const Case& c) {
    std::vector<shadel::RemapEntry> expected = c.remap;
    const uint32_t added = shadel::expandSupport(
        expected, {c.entriesPerSideLog2, c.tables.instances, c.tables.levelRects, c.tables.ownedEntries,
                   c.supportChunks});
    uint32_t counted = 0;
    const std::vector<shadel::RemapEntry> gpu = run(c, counted);
    EXPECT_GT(added, 0u);
    EXPECT_EQ(counted, added);
    size_t mismatches = 0;
    for (const auto& owned : c.tables.ownedEntries) {
      const shadel::RemapEntry& want = expected[owned.entryIndex];
      const shadel::RemapEntry& got = gpu[owned.entryIndex];
      if (got.occupancy == want.occupancy && got.storageBase == want.storageBase) continue;
      if (++mismatches <= 5)
        ADD_FAILURE() << "entry " << owned.entryIndex << " (instance " << owned.instanceId << ", level " << owned.level
                      << "): occupancy " << std::hex << got.occupancy << ", expected " << want.occupancy;
    }
    EXPECT_EQ(mismatches, 0u);
  }
};

TEST_F(SupportExpandDeviceTest, MatchesTheCppReferenceOnRandomSheets) {
  expectMatchesReference(makeCase(1, {512, 64, 256, 8, 128, 1024}));
  expectMatchesReference(makeCase(2, {64, 64, 64, 64, 32, 16, 2048}));
  expectMatchesReference(makeCase(3, {256, 512, 128, 4096}));
}

TEST_F(SupportExpandDeviceTest, MatchesTheCppReferenceBeyond65535OwnedEntries) {
  const Case c = makeCase(4, {16384, 256, 64});  // 87k owned entries
  ASSERT_GT(c.tables.ownedEntries.size(), 65535u);
  expectMatchesReference(c);
}

}  // namespace
}  // namespace sg::test
