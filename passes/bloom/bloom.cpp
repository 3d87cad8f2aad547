#include "bloom.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {

float emittedLuminance(const scene::Material& material) {
  return glm::dot(material.emissiveFactor, glm::vec3(0.2126f, 0.7152f, 0.0722f)) * material.emissiveStrength;
}

bool bloomCalledFor(const scene::Scene& scene, const render::GpuScene& gpuScene, std::span<const uint32_t> visible,
                    float threshold) {
  const auto& draws = gpuScene.draws();
  return std::any_of(visible.begin(), visible.end(), [&](uint32_t d) {
    const uint32_t m = draws[d].material;
    return m < scene.materials.size() && emittedLuminance(scene.materials[m]) >= threshold;
  });
}

gpu::ComputePipelineDesc bloomPipeline() {
  return {.shader = {.path = "passes/bloom/bloom.comp"},
          .layout = {.bindings = {{shader::kBindBloomHdr, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                  {shader::kBindBloomExposure, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindBloomSource, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                  {shader::kBindBloomTarget, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                     .pushConstantBytes = sizeof(shader::SgBloomPush)}};
}

graph::ResourceHandle addBloom(graph::RenderGraph& graph, graph::ResourceHandle hdr, graph::ResourceHandle exposure,
                               float strength, uint32_t levels) {
  // Level i is 1/2^i of the output; the steps inside the one pass are ordered by barriers of its own.
  std::vector<graph::ResourceHandle> level(levels + 1);
  for (uint32_t i = 1; i <= levels; ++i)
    level[i] = graph.createImage("bloom level " + std::to_string(i),
                                 {.format = graph::Format::RGBA16F, .size = graph::Size::relative(std::ldexp(1.0f, -int(i)))});
  auto out = graph.createImage("hdr (bloom)", {.format = graph::Format::RGBA16F});
  auto& pass = graph.addPass("bloom", graph::QueueClass::Graphics, graph::PassKind::Compute);
  pass.read(hdr, graph::Access::Sampled);
  pass.read(exposure, graph::Access::StorageRead);
  for (uint32_t i = 1; i <= levels; ++i) level[i] = pass.write(level[i], graph::Access::StorageReadWrite);
  out = pass.write(out, graph::Access::StorageWrite);
  pass.execute([hdr, exposure, level, out, strength, levels](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("bloom", bloomPipeline);
    const auto storage = [&](uint32_t binding, graph::ResourceHandle image) {
      return gpu::DescriptorWrite{binding, gpu::ImageBinding{ctx.image(image).view(), VK_IMAGE_LAYOUT_GENERAL, VK_NULL_HANDLE}};
    };
    const gpu::Scope written{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    const gpu::Scope read{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                          VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    const auto step = [&](uint32_t what, graph::ResourceHandle source, graph::ResourceHandle target, bool last) {
      ctx.bind(pipeline, {{shader::kBindBloomHdr, gpu::ImageBinding{ctx.image(hdr).view(),
                                                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                                  ctx.device().nearestSampler()}},
                          {shader::kBindBloomExposure, gpu::BufferBinding{ctx.buffer(exposure).handle()}},
                          storage(shader::kBindBloomSource, source), storage(shader::kBindBloomTarget, target)});
      const shader::SgBloomPush push{what, strength, levels};
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
      const VkExtent2D e = ctx.image(target).extent();
      vkCmdDispatch(ctx.cmd(), (e.width + 7) / 8, (e.height + 7) / 8, 1);
      if (!last) gpu::memoryBarrier(ctx.cmd(), written, read);
    };
    step(shader::kBloomStepBright, level[1], level[1], false);  // the source binding is unused by this step
    for (uint32_t i = 2; i <= levels; ++i) step(shader::kBloomStepDown, level[i - 1], level[i], false);
    for (uint32_t i = levels; i >= 2; --i) step(shader::kBloomStepUp, level[i], level[i - 1], false);
    step(shader::kBloomStepCombine, level[1], out, true);
  });
  return out;
}

}  // namespace sg::passes
