#include "shade_reuse.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindParams, kBindWork, kBindLayerImage};
}  // namespace

gpu::ComputePipelineDesc shadeReusePipeline() {
  gpu::PipelineLayoutDesc layout = decoupledLayout(kBindings, /*layerImageStorage*/ true);
  layout.bindings.push_back({kBindLayerHistory, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  return {.shader = {.path = "passes/shade-reuse/shade_reuse.comp"}, .layout = layout};
}

void addShadeReuse(graph::RenderGraph& graph, DecoupledFrame& frame) {
  auto& pass = graph.addPass("shade-reuse", graph::QueueClass::AsyncCompute);
  pass.read(frame.work, graph::Access::StorageRead);
  pass.read(frame.args, graph::Access::IndirectArgs);
  pass.read(frame.previousShaded, graph::Access::Sampled);
  frame.shadedColor = pass.write(frame.shadedColor, graph::Access::StorageWrite);
  pass.execute([frame](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("shade-reuse", shadeReusePipeline);
    const gpu::DescriptorWrite previous{
        kBindLayerHistory, gpu::ImageBinding{ctx.image(frame.previousShaded).view(),
                                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, ctx.device().nearestSampler()}};
    bindDecoupled(ctx, pipeline, frame, kBindings, {&previous, 1});
    // The reuse list's arguments follow the objects' (work_offsets.comp).
    vkCmdDispatchIndirect(ctx.cmd(), ctx.buffer(frame.args).handle(), VkDeviceSize(12) * frame.objectCount);
  });
}

}  // namespace sg::passes
