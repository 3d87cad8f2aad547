#include <glm/glm.hpp>

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

#include "environment.hpp"
#include "environment_maps.hpp"

namespace sg::passes {

gpu::ComputePipelineDesc environmentBackgroundPipeline() {
  return {.shader = {.path = "passes/environment/environment_background.comp"},
          .layout = {.bindings = {{shader::kBindEnvBackgroundSource, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindEnvBackgroundDepth, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                  {shader::kBindEnvBackgroundHdr, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                     .pushConstantBytes = sizeof(shader::SgEnvironmentBackgroundPush)}};
}

graph::ResourceHandle addEnvironmentBackground(render::FrameContext& frame, graph::ResourceHandle hdr,
                                               graph::ResourceHandle depth) {
  const scene::Environment& env = frame.inputs().scene.environment;
  if (!env.present()) return hdr;
  const auto& in = frame.inputs();
  const shader::SgEnvironmentBackgroundPush push{glm::inverse(in.viewProjection), {env.width, env.height},
                                                 {in.width, in.height}, env.intensity};
  const graph::ResourceHandle source = frame.read(kEnvironmentImageResource);
  auto& pass = frame.graph().addPass("environment-background", graph::QueueClass::Graphics, graph::PassKind::Compute);
  pass.read(source, graph::Access::StorageRead);
  pass.read(depth, graph::Access::Sampled);
  hdr = pass.write(hdr, graph::Access::StorageReadWrite);
  pass.execute([push, source, depth, hdr](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("environment-background", environmentBackgroundPipeline);
    ctx.bind(pipeline, {{shader::kBindEnvBackgroundSource, gpu::BufferBinding{ctx.buffer(source).handle()}},
                        {shader::kBindEnvBackgroundDepth,
                         gpu::ImageBinding{ctx.image(depth).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                           ctx.device().nearestSampler()}},
                        {shader::kBindEnvBackgroundHdr,
                         gpu::ImageBinding{ctx.image(hdr).view(), VK_IMAGE_LAYOUT_GENERAL, VK_NULL_HANDLE}}});
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
    vkCmdDispatch(ctx.cmd(), (push.targetSize.x + 7) / 8, (push.targetSize.y + 7) / 8, 1);
  });
  return hdr;
}

}  // namespace sg::passes
