#include "exposure.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

#include "exposure_interface.h"

namespace sg::passes {

gpu::ComputePipelineDesc exposurePipeline() {
  return {.shader = {.path = "passes/exposure/exposure.comp"},
          .layout = {.bindings = {{shader::kBindExposureHdr, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                  {shader::kBindExposure, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}}};
}

graph::ResourceHandle addExposure(graph::RenderGraph& graph, graph::ResourceHandle hdr) {
  auto exposure = graph.createBuffer("exposure", {.size = sizeof(shader::SgExposure)});
  auto& pass = graph.addPass("exposure", graph::QueueClass::AsyncCompute);
  pass.read(hdr, graph::Access::Sampled);
  exposure = pass.write(exposure, graph::Access::StorageWrite);
  pass.execute([hdr, exposure](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("exposure", exposurePipeline);
    ctx.bind(pipeline, {{shader::kBindExposureHdr, gpu::ImageBinding{ctx.image(hdr).view(),
                                                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                                     ctx.device().nearestSampler()}},
                        {shader::kBindExposure, gpu::BufferBinding{ctx.buffer(exposure).handle()}}});
    vkCmdDispatch(ctx.cmd(), 1, 1, 1);
  });
  return exposure;
}

}  // namespace sg::passes
