#include "skinning.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr uint32_t kGroupSize = 64;
}  // namespace

gpu::ComputePipelineDesc skinningPipeline() {
  return {.shader = {.path = "passes/skinning/skinning.comp"},
          .layout = {.bindings = {{shader::kBindSkinRest}, {shader::kBindSkinInfluences}, {shader::kBindSkinDeltas},
                                  {shader::kBindSkinJoints}, {shader::kBindSkinWeights}, {shader::kBindSkinVertices}},
                     .pushConstantBytes = sizeof(shader::SgSkinningPush)}};
}

graph::ResourceHandle addSkinning(graph::RenderGraph& graph, gpu::GraphExecutor& executor, const render::GpuScene& scene,
                                  const render::DeformationFrame& frame) {
  // Between frames the vertices are read by every geometry pass (vertex input,
  // or storage in layer shading) and rewritten here.
  const graph::ResourceState resting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                     graph::AccessFlag::VertexAttributeRead | graph::AccessFlag::ShaderStorageRead |
                                         graph::AccessFlag::ShaderStorageWrite};
  auto vertices = graph.importPersistentBuffer("scene vertices", {.size = scene.vertexStorage().size()}, resting);
  executor.bindBuffer(vertices, scene.vertexStorage());
  auto& pass = graph.addPass("skinning", graph::QueueClass::Graphics, graph::PassKind::Compute);
  vertices = pass.write(vertices, graph::Access::StorageWrite);
  pass.execute([&scene, frame](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("skinning", skinningPipeline);
    const render::GpuDeformation& d = frame.deformation;
    ctx.bind(pipeline, {{shader::kBindSkinRest, gpu::BufferBinding{d.rest().handle()}},
                        {shader::kBindSkinInfluences, gpu::BufferBinding{d.influences().handle()}},
                        {shader::kBindSkinDeltas, gpu::BufferBinding{d.deltas().handle()}},
                        {shader::kBindSkinJoints, gpu::BufferBinding{frame.joints.handle()}},
                        {shader::kBindSkinWeights, gpu::BufferBinding{frame.weights.handle()}},
                        {shader::kBindSkinVertices, gpu::BufferBinding{scene.vertexBuffer()}}});
    for (const render::DeformedRange& range : d.ranges()) {
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof range.push, &range.push);
      vkCmdDispatch(ctx.cmd(), (range.push.vertexCount + kGroupSize - 1) / kGroupSize, 1, 1);
    }
  });
  return vertices;
}

}  // namespace sg::passes
