#include "shade_reuse.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/material_variants.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindParams, kBindWork};
}  // namespace

gpu::ComputePipelineDesc shadeReusePipeline(graph::Format format) {
  gpu::PipelineLayoutDesc layout = decoupledLayout(kBindings);
  layout.bindings.push_back({kBindLayerImage, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
  layout.bindings.push_back({kBindLayerHistory, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  return {.shader = {.path = "passes/shade-reuse/shade_reuse.comp",
                     .defines = {{"SG_REUSE_FORMAT", render::glslImageFormat(format)}}},
          .layout = layout};
}

void addShadeReuse(graph::RenderGraph& graph, DecoupledFrame& frame, std::vector<KeptLayerImage>& layers) {
  auto& pass = graph.addPass("shade-reuse", graph::QueueClass::AsyncCompute);
  pass.read(frame.work, graph::Access::StorageRead);
  pass.read(frame.args, graph::Access::IndirectArgs);
  std::vector<KeptLayerImage> copies;
  for (auto& layer : layers) {
    pass.read(layer.history, graph::Access::Sampled);
    layer.current = pass.write(layer.current, graph::Access::StorageWrite);
    copies.push_back(layer);
  }
  pass.execute([frame, copies](PassContext& ctx) {
    for (const auto& copy : copies) {
      const std::string format = render::glslImageFormat(copy.format);
      const auto& pipeline =
          ctx.device().pipeline("shade-reuse/" + format, [&] { return shadeReusePipeline(copy.format); });
      const std::array<gpu::DescriptorWrite, 2> images{
          gpu::DescriptorWrite{kBindLayerImage,
                               gpu::ImageBinding{ctx.image(copy.current).view(), VK_IMAGE_LAYOUT_GENERAL, VK_NULL_HANDLE}},
          gpu::DescriptorWrite{kBindLayerHistory,
                               gpu::ImageBinding{ctx.image(copy.history).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                 ctx.device().nearestSampler()}}};
      bindDecoupled(ctx, pipeline, frame, kBindings, images);
      // The reuse list's arguments follow the objects' (work_offsets.comp).
      vkCmdDispatchIndirect(ctx.cmd(), ctx.buffer(frame.args).handle(), VkDeviceSize(12) * frame.objectCount);
    }
  });
}

}  // namespace sg::passes
