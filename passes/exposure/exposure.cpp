#include "exposure.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {

graph::ResourceHandle addExposure(graph::RenderGraph& graph, graph::ResourceHandle hdr) {
  auto exposure = graph.createBuffer("exposure", {.size = 16});
  auto& pass = graph.addPass("exposure", graph::QueueClass::AsyncCompute);
  pass.read(hdr, graph::Access::Sampled);
  exposure = pass.write(exposure, graph::Access::StorageWrite);
  pass.execute([hdr, exposure](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("exposure", [] {
      return gpu::ComputePipelineDesc{
          .shader = {.path = "passes/exposure/exposure.comp"},
          .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}}};
    });
    ctx.bind(pipeline, {{0, gpu::ImageBinding{ctx.image(hdr).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                              ctx.device().nearestSampler()}},
                        {1, gpu::BufferBinding{ctx.buffer(exposure).handle()}}});
    vkCmdDispatch(ctx.cmd(), 1, 1, 1);
  });
  return exposure;
}

}  // namespace sg::passes
