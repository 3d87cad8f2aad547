#include "layer_shade.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {

void addLayerShade(graph::RenderGraph& graph, render::DecoupledFrame& frame) {
  auto& pass = graph.addPass("layer-shade", graph::QueueClass::AsyncCompute);
  pass.read(frame.work, graph::Access::StorageRead);
  pass.read(frame.args, graph::Access::IndirectArgs);
  frame.layerImage = pass.write(frame.layerImage, graph::Access::StorageWrite);
  pass.execute([frame](PassContext& ctx) {
    using namespace render;
    const std::array bindings{kBindFrame, kBindParams, kBindObjects, kBindShadelInstances, kBindLevelRects,
                               kBindWork, kBindIdMaps, kBindVertices, kBindIndices, kBindLayerImage};
    const auto& pipeline = ctx.device().pipeline("layer-shade/gltf-pbr", [&] {
      return gpu::ComputePipelineDesc{
          .shader = {.path = "passes/layer-shade/layer_shade.comp"},
          .layout = decoupledLayout(bindings, true, 8, {frame.view.scene.materialSetLayout()})};
    });
    bindDecoupled(ctx, pipeline, frame, bindings);
    const VkBuffer args = ctx.buffer(frame.args).handle();
    const auto& draws = frame.view.scene.draws();
    for (uint32_t object = 0; object < frame.objectCount; ++object) {
      VkDescriptorSet material = frame.view.scene.materialSet(draws[frame.objectDraws[object]].material);
      vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 1, 1, &material, 0, nullptr);
      for (uint32_t layer = 0; layer < frame.layerCount; ++layer) {
        const uint32_t push[2] = {object, layer};
        vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, push);
        vkCmdDispatchIndirect(ctx.cmd(), args, VkDeviceSize(12) * (object * frame.layerCount + layer));
      }
    }
  });
}

}  // namespace sg::passes
