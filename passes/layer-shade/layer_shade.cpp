#include "layer_shade.hpp"

#include <map>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/light_binding.hpp>
#include <shadelgraph/render/material_variants.hpp>
#include <shadelgraph/render/environment_binding.hpp>
#include <shadelgraph/render/shadow_binding.hpp>

#include "layer_variant.hpp"

namespace sg::passes {
namespace {

constexpr uint32_t kBaseBindings[] = {kBindFrame,    kBindParams,   kBindObjects,  kBindShadelInstances,
                                      kBindLevelRects, kBindRemap,  kBindCounters, kBindWork,
                                      kBindIdMaps,   kBindVertices, kBindIndices, kBindChunkSlots,
                                      kBindShadelMasks};

// Compiled the first time a frame dispatches the layer; a GLSL error names the
// layer, its plugin and the author's file:line.
const gpu::Pipeline& layerPipeline(PassContext& ctx, const DecoupledFrame& frame, const plugin::MaterialLayer& layer) {
  const render::TextureSet* textures = frame.view.layerTextures.forLayer(layer);
  const uint32_t invocations =
      frame.layerShadeInvocations != 0 ? frame.layerShadeInvocations : ctx.device().context().subgroupSize();
  const uint32_t rows = chunkRowsPerInvocation(invocations);
  const auto describe = [&] {
    gpu::ComputePipelineDesc desc = layerShadePipeline(layer, rows);
    desc.layout.extraSets.push_back(frame.view.scene.materialSetLayout());
    if (textures) desc.layout.extraSets.push_back(textures->layout());
    return desc;
  };
  try {
    return ctx.device().pipeline("layer-shade/" + layer.name + "/rows" + std::to_string(rows), describe);
  } catch (const gpu::ShaderCompileError& e) {
    throw render::layerCompileError(e, ctx.device().shaders(), "material layer '" + layer.name + "'", layer.plugin);
  }
}

}  // namespace

gpu::ComputePipelineDesc layerShadePipeline(const plugin::MaterialLayer& layer, uint32_t rowsPerInvocation) {
  gpu::PipelineLayoutDesc layout = decoupledLayout(kBaseBindings, false, sizeof(SgLayerShadePush));
  layout.bindings.push_back({kBindLayerOutput, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
  layout.bindings.push_back(render::shadowMapsBinding());
  for (const auto& b : render::environmentBindings()) layout.bindings.push_back(b);
  for (const auto& binding : render::lightBindings()) layout.bindings.push_back(binding);
  for (uint32_t i = 0; i < layer.reads.size(); ++i)
    layout.bindings.push_back({kBindLayerInputs + i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  for (uint32_t i = 0; i < layer.frameInputs.size(); ++i)
    layout.bindings.push_back({render::kBindLayerFrameInputs + i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  if (layer.keepsValues()) {
    layout.bindings.push_back({kBindLayerHistory, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  }
  return {.shader = decoupledLayerVariant(layer, rowsPerInvocation), .layout = layout};
}

void addLayerShade(graph::RenderGraph& graph, DecoupledFrame& frame, std::string name,
                   std::vector<LayerShadeStep>& steps, const LayerHistory& history) {
  auto& pass = graph.addPass(std::move(name), graph::QueueClass::AsyncCompute);
  pass.read(frame.work, graph::Access::StorageRead);
  pass.read(frame.args, graph::Access::IndirectArgs);
  pass.read(frame.remap, graph::Access::StorageRead);
  pass.read(frame.slots, graph::Access::StorageRead);
  const bool masks = frame.shadelMasks && frame.masks.valid();
  if (masks) pass.read(frame.masks, graph::Access::StorageRead);
  render::readShadowMaps(pass, frame.view, graph::ShaderStage::Compute);
  render::readSceneGeometry(pass, frame.view, graph::Access::Sampled, graph::ShaderStage::Compute);  // a texel buffer
  render::readEnvironment(pass, frame.view, graph::ShaderStage::Compute);
  render::readLightGrid(pass, frame.view, graph::ShaderStage::Compute);
  bool persistent = false;
  std::map<graph::ResourceHandle, graph::ResourceHandle> written;  // each output once, however many steps write it
  for (auto& step : steps) {
    for (const auto input : step.inputs) pass.read(input, graph::Access::Sampled);
    for (const auto input : step.frameInputs) pass.read(input, graph::Access::Sampled);
    if (step.layer->keepsValues()) {
      pass.read(step.history, graph::Access::Sampled);
      persistent = true;
    }
    auto [it, added] = written.try_emplace(step.output);
    if (added) it->second = pass.write(step.output, graph::Access::StorageWrite);
  }
  // The steps that write the shaded colour count the shadels the masks leave out.
  std::vector<bool> counts;
  for (const auto& step : steps) counts.push_back(masks && step.output == frame.shadedColor);
  if (persistent || masks) {
    frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);  // layer_reuse, shadelsSkipped
  }
  for (auto& step : steps) step.output = written.at(step.output);

  pass.execute([frame, steps, history, masks, counts](PassContext& ctx) {
    const VkBuffer args = ctx.buffer(frame.args).handle();
    const auto& draws = frame.view.scene.draws();
    const auto sampled = [&](uint32_t binding, graph::ResourceHandle image) {
      return gpu::DescriptorWrite{binding, gpu::ImageBinding{ctx.image(image).view(),
                                                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                             ctx.device().nearestSampler()}};
    };
    for (size_t stepIndex = 0; stepIndex < steps.size(); ++stepIndex) {
      const LayerShadeStep& step = steps[stepIndex];
      const auto& pipeline = layerPipeline(ctx, frame, *step.layer);
      std::vector<gpu::DescriptorWrite> writes{
          {kBindLayerOutput, gpu::ImageBinding{ctx.image(step.output).view(), VK_IMAGE_LAYOUT_GENERAL, VK_NULL_HANDLE}},
          render::shadowMapsWrite(ctx, frame.view)};
      for (const auto& w : render::environmentWrites(ctx, frame.view)) writes.push_back(w);
      for (const auto& write : render::lightWrites(ctx, frame.view)) writes.push_back(write);
      for (uint32_t i = 0; i < step.inputs.size(); ++i) writes.push_back(sampled(kBindLayerInputs + i, step.inputs[i]));
      for (uint32_t i = 0; i < step.frameInputs.size(); ++i)
        writes.push_back(sampled(render::kBindLayerFrameInputs + i, step.frameInputs[i]));
      if (step.layer->keepsValues()) {
        writes.push_back(sampled(kBindLayerHistory, step.history));
      }
      bindDecoupled(ctx, pipeline, frame, kBaseBindings, writes);
      if (const render::TextureSet* textures = frame.view.layerTextures.forLayer(*step.layer)) {
        VkDescriptorSet set = textures->set();
        vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), render::kLayerTextureSet, 1, &set,
                                0, nullptr);
      }
      for (const uint32_t object : step.objects) {
        VkDescriptorSet material = frame.view.scene.materialSet(draws[frame.objectDraws[object]].material);
        vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 1, 1, &material, 0,
                                nullptr);
        const SgLayerShadePush push{object, step.persistentSlot, history.valid ? 1u : 0u, masks ? 1u : 0u,
                                    counts[stepIndex] ? 1u : 0u};
        vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
        vkCmdDispatchIndirect(ctx.cmd(), args, VkDeviceSize(12) * object);
      }
    }
  });
}

}  // namespace sg::passes
