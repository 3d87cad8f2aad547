#include "occlusion_cull.hpp"

#include <algorithm>

#include <shadelgraph/gpu/pass_context.hpp>

#include "occlusion_interface.h"

namespace sg::passes {
namespace {

constexpr uint32_t kCommandBytes = sizeof(VkDrawIndexedIndirectCommand);
static_assert(kCommandBytes == 20, "occlusion_cull.comp's DrawCommand");

uint32_t groups(uint32_t n, uint32_t size) { return (n + size - 1) / size; }

}  // namespace

gpu::ComputePipelineDesc hiZPipeline() {
  return {.shader = {.path = "passes/occlusion-cull/hi_z.comp"},
          .layout = {.bindings = {{shader::kBindCullDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                  {shader::kBindCullTiles, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                     .pushConstantBytes = sizeof(shader::SgCullConstants)}};
}

gpu::ComputePipelineDesc occlusionCullPipeline() {
  return {.shader = {.path = "passes/occlusion-cull/occlusion_cull.comp"},
          .layout = {.bindings = {{shader::kBindCullTiles, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindCullSpheres, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindCullCommands, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindCullLate, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                     .pushConstantBytes = sizeof(shader::SgCullConstants)}};
}

OcclusionCullResult addOcclusionCull(graph::RenderGraph& graph, const render::DrawCulling& culling,
                                     const glm::mat4& viewProjection, uint32_t width, uint32_t height,
                                     graph::ResourceHandle depth, graph::ResourceHandle commands) {
  const shader::SgCullConstants constants{viewProjection, culling.drawCount(), width, height,
                                          groups(width, shader::kCullTileSize), groups(height, shader::kCullTileSize)};
  auto tiles = graph.createBuffer("depth tiles", {.size = uint64_t(constants.tilesX) * constants.tilesY * 4});
  auto& hiZ = graph.addPass("hi-z", graph::QueueClass::Graphics, graph::PassKind::Compute);
  hiZ.read(depth, graph::Access::Sampled);
  tiles = hiZ.write(tiles, graph::Access::StorageWrite);
  hiZ.execute([constants, depth, tiles](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("hi-z", hiZPipeline);
    ctx.bind(pipeline, {{shader::kBindCullDepth, gpu::ImageBinding{ctx.image(depth).view(),
                                                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                                  ctx.device().nearestSampler()}},
                        {shader::kBindCullTiles, gpu::BufferBinding{ctx.buffer(tiles).handle()}}});
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof constants, &constants);
    vkCmdDispatch(ctx.cmd(), groups(constants.tilesX, 8), groups(constants.tilesY, 8), 1);
  });

  OcclusionCullResult out;
  out.late = graph.createBuffer("late draw commands", {.size = std::max<uint64_t>(uint64_t(culling.drawCount()) * kCommandBytes, 20)});
  auto& cull = graph.addPass("occlusion-cull", graph::QueueClass::Graphics, graph::PassKind::Compute);
  cull.read(tiles, graph::Access::StorageRead);
  out.commands = cull.write(commands, graph::Access::StorageReadWrite);
  out.late = cull.write(out.late, graph::Access::StorageWrite);
  const VkBuffer spheres = culling.spheres().handle();
  cull.execute([constants, tiles, spheres, out](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("occlusion-cull", occlusionCullPipeline);
    ctx.bind(pipeline, {{shader::kBindCullTiles, gpu::BufferBinding{ctx.buffer(tiles).handle()}},
                        {shader::kBindCullSpheres, gpu::BufferBinding{spheres}},
                        {shader::kBindCullCommands, gpu::BufferBinding{ctx.buffer(out.commands).handle()}},
                        {shader::kBindCullLate, gpu::BufferBinding{ctx.buffer(out.late).handle()}}});
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof constants, &constants);
    vkCmdDispatch(ctx.cmd(), groups(constants.drawCount, 64), 1, 1);
  });
  return out;
}

}  // namespace sg::passes
