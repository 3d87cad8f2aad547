// shadel-mark's level formula (passes/shadel-mark/shadel_mark_levels.glsl),
// run on lavapipe, against the tables it stands in for: the level rectangle
// and the mask slot (the owned-entry index shadel-clear gives the remap
// entry, times the chunk slots per entry) that shadel::buildGpuTables gives,
// for every power-of-two level-0 size from 1 to 2^16 shadels, several
// minimum level sizes, and shadel spaces fragmented by releases (so
// instances start at many owned-entry indices and origins).
#include "../../device/device_fixture.hpp"

#include <random>
#include <string>
#include <unordered_map>
#include <vector>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/shadel/remap_entry.hpp>
#include <shadelgraph/shadel/shadel_gpu_tables.hpp>
#include <shadelgraph/shadel/shadel_space.hpp>

namespace sg::test {
namespace {

constexpr const char* kShaderPath = "tests/shadel/mark_levels.comp";

// Per case (instance, level, shadel offset in the level): the instance's
// levels as shadel-mark's vertex shader hands them on, the level as its
// fragment shader derives it; out: the rectangle's origin and size and the
// mask slot base of the shadel's entry.
constexpr const char* kShader = R"(#version 460
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "framework/shadel/shaders/decoupled_interface.h"
#include "framework/shadel/shaders/shadel_address.glsl"
#include "passes/shadel-mark/shadel_mark_levels.glsl"
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Instances { SgShadelInstance instances[]; };
layout(std430, set = 0, binding = 1) readonly buffer Rects { SgLevelRect levelRects[]; };
layout(std430, set = 0, binding = 2) readonly buffer Cases { uvec4 cases[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Results { uvec4 results[]; };
layout(push_constant) uniform Push { uint count; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  SgShadelInstance instance = instances[cases[i].x];
  uvec4 levels = uvec4(instance.level0Size, instance.levelCount, instance.firstOwnedEntry, instance.firstLevelRect);
  SgMarkLevel level = sgMarkLevel(levels, cases[i].y, levelRects[levels.w + cases[i].y]);
  uvec2 shadel = level.rect.origin + cases[i].zw;
  results[i] = uvec4(level.rect.origin, level.rect.size, sgMarkStorageBase(level, shadel));
}
)";

struct Case {
  uint32_t instance, level, x, y;
};

// A space holding every power-of-two level-0 size up to 2^maxLog2 with the
// given minimum level size, some released again and others allocated in
// their holes.
shadel::ShadelSpace makeSpace(uint32_t sheetSizeLog2, uint32_t maxLog2, uint32_t minLevelSize, uint32_t seed) {
  std::mt19937 rng(seed);
  shadel::ShadelSpace space({.sheetSizeLog2 = sheetSizeLog2});
  uint32_t id = 0;
  std::vector<uint32_t> ids;
  for (int round = 0; round < 2; ++round) {
    for (uint32_t log2 = 0; log2 <= maxLog2; ++log2) {
      const auto levels = shadel::makeDetailLevels(1u << log2, minLevelSize);
      if (levels.levelCount == 0) continue;
      EXPECT_TRUE(space.allocate(id, levels).ok()) << "level 0 " << (1u << log2);
      ids.push_back(id++);
    }
    if (round == 0)  // holes: later instances land between earlier ones
      for (const uint32_t i : ids)
        if (rng() % 2) space.release(i);
    maxLog2 = std::min(maxLog2, 12u);
  }
  return space;
}

class MarkLevelsDeviceTest : public DeviceTest {
 protected:
  template <class T>
  gpu::Buffer storage(const std::vector<T>& data, const char* name) {
    gpu::Buffer buffer(*context, *memory,
                       {std::max<size_t>(data.size() * sizeof(T), 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        gpu::MemoryLocation::Upload, name});
    if (!data.empty()) buffer.write(data.data(), data.size() * sizeof(T));
    return buffer;
  }

  // Every level of every instance: its corners and random shadels inside.
  void check(const shadel::ShadelSpace& space, uint32_t seed) {
    const shadel::ShadelGpuTables tables = shadel::buildGpuTables(space);
    const uint32_t log2 = space.geometry().entriesPerSideLog2();
    std::unordered_map<uint32_t, uint32_t> ownedIndex;  // remap entry -> owned-entry index (shadel-clear's storageBase / 64)
    for (uint32_t i = 0; i < tables.ownedEntries.size(); ++i) ownedIndex[tables.ownedEntries[i].entryIndex] = i;
    std::mt19937 rng(seed);
    std::vector<Case> cases;
    for (uint32_t id = 0; id < tables.instances.size(); ++id) {
      const auto& instance = tables.instances[id];
      for (uint32_t level = 0; level < instance.levelCount; ++level) {
        const uint32_t size = tables.levelRects[instance.firstLevelRect + level].size;
        const uint32_t last = size - 1;
        for (const auto& [x, y] : {std::pair{0u, 0u}, {last, 0u}, {0u, last}, {last, last}})
          cases.push_back({id, level, x, y});
        for (int i = 0; i < 6; ++i) cases.push_back({id, level, uint32_t(rng() % size), uint32_t(rng() % size)});
      }
    }
    ASSERT_GT(cases.size(), 100u);
    const auto results = run(tables, cases);
    size_t mismatches = 0;
    for (size_t i = 0; i < cases.size() && mismatches < 10; ++i) {
      const Case& c = cases[i];
      const auto& instance = tables.instances[c.instance];
      const shadel::LevelRect& rect = tables.levelRects[instance.firstLevelRect + c.level];
      const glm::uvec2 shadel = rect.origin + glm::uvec2(c.x, c.y);
      const glm::uvec2 entry = shadel >> shadel::kEntrySizeLog2;
      const auto owned = ownedIndex.find((entry.y << log2) | entry.x);
      ASSERT_NE(owned, ownedIndex.end()) << "shadel outside the owned entries";
      ASSERT_EQ(tables.ownedEntries[owned->second].instanceId, c.instance);
      ASSERT_EQ(tables.ownedEntries[owned->second].level, c.level);
      const glm::uvec4 expected(rect.origin, rect.size, owned->second * shadel::kChunksPerEntry);
      if (results[i] != expected) {
        ++mismatches;
        ADD_FAILURE() << "level 0 " << instance.level0Size << " level " << c.level << " of " << instance.levelCount
                      << " shadel +(" << c.x << "," << c.y << "): GLSL origin (" << results[i].x << "," << results[i].y
                      << ") size " << results[i].z << " slot " << results[i].w << ", tables (" << expected.x << ","
                      << expected.y << ") " << expected.z << " " << expected.w;
      }
    }
  }

  std::vector<glm::uvec4> run(const shadel::ShadelGpuTables& tables, const std::vector<Case>& cases) {
    gpu::Pipeline pipeline(*context, *compiler, *pipelineCache,
                           gpu::ComputePipelineDesc{.shader = {.path = kShaderPath},
                                                    .layout = {.bindings = {{0}, {1}, {2}, {3}}, .pushConstantBytes = 4}});
    gpu::Buffer instances = storage(tables.instances, "instances");
    gpu::Buffer rects = storage(tables.levelRects, "level rects");
    gpu::Buffer in = storage(cases, "cases");
    gpu::Buffer out(*context, *memory,
                    {cases.size() * sizeof(glm::uvec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Readback,
                     "results"});
    gpu::DescriptorArena descriptors(*context);
    const auto count = uint32_t(cases.size());
    context->submitAndWait([&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.handle());
      descriptors.bind(cmd, pipeline,
                       {{0, gpu::BufferBinding{instances.handle()}},
                        {1, gpu::BufferBinding{rects.handle()}},
                        {2, gpu::BufferBinding{in.handle()}},
                        {3, gpu::BufferBinding{out.handle()}}});
      vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof count, &count);
      vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
      gpu::hostReadAfterCompute(cmd);
    });
    const auto view = out.view<glm::uvec4>();
    return {view.begin(), view.end()};
  }
};

// The default sheet (2^16 shadels a side), instances up to level 0 = 2^14,
// minimum level sizes 1, 8 (the default) and 64; and a 2^19 sheet (the
// largest the packed origins hold) with a level 0 of 2^16.
TEST_F(MarkLevelsDeviceTest, ShadelGlslMarkLevelsMatchGpuTables) {
  library.addDirectory(SG_SOURCE_DIR);
  library.add(kShaderPath, kShader);
  for (const uint32_t minLevelSize : {1u, 8u, 64u}) {
    SCOPED_TRACE("minimum level size " + std::to_string(minLevelSize));
    check(makeSpace(16, 14, minLevelSize, minLevelSize), 7 + minLevelSize);
  }
  SCOPED_TRACE("2^19 sheet");
  check(makeSpace(19, 16, shadel::kDefaultMinLevelSize, 19), 19);
}

}  // namespace
}  // namespace sg::test
