#include "light_cull.hpp"

#include <algorithm>
#include <cmath>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/shaders/frame_interface.h>

namespace sg::passes {

shader::SgLightGridHeader lightGridFor(uint32_t width, uint32_t height, const glm::mat4& viewProjection,
                                       std::span<const glm::vec4> visibleSpheres, uint32_t lightCount) {
  const auto tiles = [](uint32_t pixels) {
    return std::clamp((pixels + shader::kLightGridTilePixels - 1) / shader::kLightGridTilePixels, 1u,
                      shader::kLightGridMaxTiles);
  };
  // Clip w of a world point is the row 3 of the view-projection (view depth for a perspective camera).
  const glm::vec4 row3(viewProjection[0][3], viewProjection[1][3], viewProjection[2][3], viewProjection[3][3]);
  const float scale = glm::length(glm::vec3(row3));
  float nearest = INFINITY, farthest = 0.0f;
  for (const glm::vec4& s : visibleSpheres) {
    const float w = glm::dot(row3, glm::vec4(glm::vec3(s), 1.0f));
    nearest = std::min(nearest, w - s.w * scale);
    farthest = std::max(farthest, w + s.w * scale);
  }
  if (!(farthest > 0.0f)) farthest = 1.0f;
  // A camera inside a sphere: the slices start at 1/1000 of the depth, nearer points loop over every light.
  nearest = std::clamp(nearest, farthest * 1e-3f, farthest);
  // An orthographic camera (w = 1 everywhere) or a thin range gets one slice.
  const uint32_t slices = farthest > nearest * 1.01f ? shader::kLightGridSlices : 1u;
  nearest *= 0.999f;
  farthest *= 1.001f;
  shader::SgLightGridHeader grid{};
  grid.dims = glm::uvec4(tiles(width), tiles(height), slices, std::min(lightCount, shader::kLightGridMaxPerCluster));
  grid.depth = glm::vec4(nearest, farthest, float(slices) / std::log(farthest / nearest), 0.0f);
  return grid;
}

uint64_t lightGridBytes(const shader::SgLightGridHeader& grid) {
  const uint64_t clusters = uint64_t(grid.dims.x) * grid.dims.y * grid.dims.z;
  return sizeof grid + clusters * (grid.dims.w + 1) * sizeof(uint32_t);
}

gpu::ComputePipelineDesc lightCullPipeline() {
  return {.shader = {.path = "passes/light-cull/light_cull.comp"},
          .layout = {.bindings = {{shader::kBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                  {shader::kBindLights, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindLightGrid, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                     .pushConstantBytes = sizeof(shader::SgLightCullPush)}};
}

graph::ResourceHandle addLightCull(graph::RenderGraph& graph, const render::SceneView& view,
                                   const shader::SgLightGridHeader& grid, uint32_t lightCount) {
  auto buffer = graph.createBuffer("light grid", {.size = lightGridBytes(grid)});
  auto& pass = graph.addPass("light-cull", graph::QueueClass::Graphics, graph::PassKind::Compute);
  buffer = pass.write(buffer, graph::Access::StorageWrite);
  const shader::SgLightCullPush push{grid, lightCount};
  pass.execute([view, buffer, push](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("light-cull", lightCullPipeline);
    ctx.bind(pipeline, {{shader::kBindFrame, gpu::BufferBinding{view.frameUniforms.handle()}},
                        {shader::kBindLights, gpu::BufferBinding{view.lights.handle()}},
                        {shader::kBindLightGrid, gpu::BufferBinding{ctx.buffer(buffer).handle()}}});
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
    const uint32_t clusters = push.grid.dims.x * push.grid.dims.y * push.grid.dims.z;
    vkCmdDispatch(ctx.cmd(), (clusters + 63) / 64, 1, 1);
  });
  return buffer;
}

}  // namespace sg::passes
