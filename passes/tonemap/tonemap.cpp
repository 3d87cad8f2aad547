#include "tonemap.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

#include "exposure/exposure_interface.h"

namespace sg::passes {

gpu::GraphicsPipelineDesc tonemapPipeline(VkFormat output, bool passthrough) {
  gpu::GraphicsPipelineDesc desc{
      .vertex = {.path = "framework/render/shaders/fullscreen.vert"},
      .fragment = {.path = "passes/tonemap/tonemap.frag"},
      .layout = {.bindings = {{shader::kBindExposureHdr, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                              {shader::kBindExposure, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}},
      .colorFormats = {output}};
  if (passthrough) desc.fragment.defines.push_back({"SG_TONEMAP_PASSTHROUGH", "1"});
  return desc;
}

graph::ResourceHandle addTonemap(graph::RenderGraph& graph, graph::ResourceHandle hdr, graph::ResourceHandle exposure,
                                 graph::ResourceHandle output, bool passthrough) {
  auto& pass = graph.addPass("tonemap", graph::QueueClass::Graphics);
  pass.read(hdr, graph::Access::Sampled);
  pass.read(exposure, graph::Access::StorageRead);
  output = pass.write(output, graph::Access::ColorAttachment);
  pass.execute([hdr, exposure, output, passthrough](PassContext& ctx) {
    const VkFormat format = ctx.image(output).desc().format;
    const auto& pipeline = ctx.device().pipeline("tonemap/" + std::to_string(format) + (passthrough ? "/pass" : ""),
                                                 [&] { return tonemapPipeline(format, passthrough); });
    ctx.beginRendering({ColorTarget{output}});
    ctx.bind(pipeline, {{shader::kBindExposureHdr, gpu::ImageBinding{ctx.image(hdr).view(),
                                                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                                     ctx.device().nearestSampler()}},
                        {shader::kBindExposure, gpu::BufferBinding{ctx.buffer(exposure).handle()}}});
    vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    ctx.endRendering();
  });
  return output;
}

}  // namespace sg::passes
