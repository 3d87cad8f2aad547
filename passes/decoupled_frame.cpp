#include <decoupled_frame.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/shadel/level_selection.hpp>
#include <shadelgraph/shadel/remap_entry.hpp>

namespace sg::passes {

std::pair<std::string, std::string> filterDefine(int filter) {
  if (filter < 0 || filter > 2)
    throw std::invalid_argument("composite filter " + std::to_string(filter) + " (0 point, 1 bilinear, 2 trilinear)");
  return {"SG_FILTER", std::to_string(filter)};
}

std::vector<std::pair<std::string, std::string>> levelRuleDefines(uint32_t levelRule) {
  return shadel::levelRuleDefines(shadel::unpackLevelRule(levelRule));
}

std::string levelRuleVariant(uint32_t levelRule) {
  if (levelRule == 0) return {};
  char hex[16];
  std::snprintf(hex, sizeof hex, "%08x", levelRule);
  return std::string("/rule-") + hex;
}

gpu::PipelineLayoutDesc decoupledLayout(std::span<const uint32_t> bindings, bool layerImageStorage,
                                        uint32_t pushConstantBytes,
                                        std::initializer_list<VkDescriptorSetLayout> extraSets) {
  gpu::PipelineLayoutDesc layout{.extraSets = extraSets, .pushConstantBytes = pushConstantBytes};
  for (uint32_t b : bindings) {
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (b == kBindFrame || b == kBindParams) type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    if (b == kBindIdMaps || b == kBindVertices || b == kBindIndices || b == kBindRemapTexels ||
        b == kBindShadelMaskTexels || b == kBindShadelMaskPairTexels || b == kBindLevelRectTexels ||
        b == kBindChunkSlotTexels)
      type = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    if (b == kBindMarkRequests) type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    if (b == kBindLayerImage)
      type = layerImageStorage ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    layout.bindings.push_back({b, type});
  }
  return layout;
}

void bindDecoupled(PassContext& ctx, const gpu::Pipeline& pipeline, const DecoupledFrame& f,
                   std::span<const uint32_t> bindings, std::span<const gpu::DescriptorWrite> extra) {
  std::vector<gpu::DescriptorWrite> writes(extra.begin(), extra.end());
  for (uint32_t b : bindings) {
    auto buffer = [&](VkBuffer vk) { writes.push_back({b, gpu::BufferBinding{vk}}); };
    switch (b) {
      case kBindFrame: buffer(f.view.frameUniforms.handle()); break;
      case kBindParams: buffer(f.params.handle()); break;
      case kBindObjects: buffer(f.objects.handle()); break;
      case kBindShadelInstances: buffer(f.shadelInstances.handle()); break;
      case kBindLevelRects: buffer(f.levelRects.handle()); break;
      case kBindRemap: buffer(ctx.buffer(f.remap).handle()); break;
      case kBindOwnedEntries: buffer(f.ownedEntries.handle()); break;
      // Without stamps something must be bound; the shaders do not touch it (params.stampsBound 0).
      case kBindShadeStamps: buffer(ctx.buffer(f.stamps.valid() ? f.stamps : f.work).handle()); break;
      case kBindChunkSlots: buffer(ctx.buffer(f.slots).handle()); break;
      // Without masks something must be bound; the shaders do not touch it (shadelMasks 0).
      case kBindShadelMasks: buffer(ctx.buffer(f.masks.valid() ? f.masks : f.work).handle()); break;
      // Without blocks something must be bound; the shaders read it only with SgEntrySpan.blocks.
      case kBindEntryBlocks: buffer(ctx.buffer(f.entryBlocks.valid() ? f.entryBlocks : f.work).handle()); break;
      case kBindCounters: buffer(ctx.buffer(f.counters).handle()); break;
      case kBindWork: buffer(ctx.buffer(f.work).handle()); break;
      case kBindArgs: buffer(ctx.buffer(f.args).handle()); break;
      case kBindIdMaps: writes.push_back({b, gpu::TexelBufferBinding{f.idMaps}}); break;
      case kBindVertices: writes.push_back({b, gpu::TexelBufferBinding{f.view.scene.vertexTexels()}}); break;
      case kBindIndices: writes.push_back({b, gpu::TexelBufferBinding{f.view.scene.indexTexels()}}); break;
      case kBindRemapTexels:
        writes.push_back(
            {b, gpu::TexelBufferBinding{ctx.buffer(f.remap).texelView(ctx.device().context(), VK_FORMAT_R32G32B32A32_UINT,
                                                                      sizeof(shadel::RemapEntry))}});
        break;
      case kBindLevelRectTexels:
        writes.push_back({b, gpu::TexelBufferBinding{f.levelRects.texelView(
                                 ctx.device().context(), VK_FORMAT_R32G32B32A32_UINT, sizeof(shadel::LevelRect))}});
        break;
      case kBindChunkSlotTexels:
        writes.push_back({b, gpu::TexelBufferBinding{
                                 ctx.buffer(f.slots).texelView(ctx.device().context(), VK_FORMAT_R32_UINT, 4)}});
        break;
      case kBindShadelMaskTexels:
        writes.push_back({b, gpu::TexelBufferBinding{ctx.buffer(f.masks).texelView(
                                 ctx.device().context(), VK_FORMAT_R32G32_UINT, sizeof(uint64_t))}});
        break;
      case kBindShadelMaskPairTexels:
        writes.push_back({b, gpu::TexelBufferBinding{ctx.buffer(f.masks).texelView(
                                 ctx.device().context(), VK_FORMAT_R32G32B32A32_UINT, 2 * sizeof(uint64_t))}});
        break;
      case kBindMarkRequests:
        writes.push_back({b, gpu::ImageBinding{ctx.image(f.markRequests).view(), VK_IMAGE_LAYOUT_GENERAL}});
        break;
      case kBindLayerImage: {
        const auto& pipelineBindings = pipeline.bindings();
        bool storage = false;
        for (const auto& pb : pipelineBindings)
          if (pb.binding == b) storage = pb.type == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
        writes.push_back({b, gpu::ImageBinding{ctx.image(f.shadedColor).view(),
                                               storage ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                               storage ? VK_NULL_HANDLE : ctx.device().nearestSampler()}});
        break;
      }
    }
  }
  vkCmdBindPipeline(ctx.cmd(), pipeline.bindPoint(), pipeline.handle());
  ctx.descriptors().bind(ctx.cmd(), pipeline, writes);
}

void dispatchEntrySpans(PassContext& ctx, const gpu::Pipeline& pipeline, const DecoupledFrame& frame,
                        uint32_t entriesPerGroup) {
  if (frame.entryBlocks.valid()) {
    const SgEntrySpan blocks{0, 0, 1};
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof blocks, &blocks);
    vkCmdDispatchIndirect(ctx.cmd(), ctx.buffer(frame.entryBlocks).handle(),
                          entriesPerGroup == 32 ? offsetof(SgEntryBlocksHeader, args32) : offsetof(SgEntryBlocksHeader, args64));
    return;
  }
  constexpr uint32_t kMaxGroupsPerRow = 65535;  // maxComputeWorkGroupCount[0]'s guaranteed minimum
  for (const SgEntrySpan& span : frame.liveSpans) {
    if (span.end <= span.begin) continue;
    const SgEntrySpan push{span.begin, span.end, 0};
    const uint32_t groups = (span.end - span.begin + entriesPerGroup - 1) / entriesPerGroup;
    const uint32_t x = std::min(groups, kMaxGroupsPerRow);
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
    vkCmdDispatch(ctx.cmd(), x, (groups + x - 1) / x, 1);
  }
}

void readEntryBlocks(graph::Pass& pass, const DecoupledFrame& frame) {
  if (!frame.entryBlocks.valid()) return;
  pass.read(frame.entryBlocks, graph::Access::StorageRead);
  pass.read(frame.entryBlocks, graph::Access::IndirectArgs);
}

void drawDecoupled(PassContext& ctx, const DecoupledFrame& frame, std::span<const uint32_t> bindings, VkBuffer indirect,
                   const std::function<const gpu::Pipeline&(bool alphaTest, uint32_t levelRule)>& pipeline,
                   bool reverseOpaque) {
  const auto& draws = frame.view.scene.draws();
  const auto levelRuleOf = [&](size_t i) {
    const uint32_t object = frame.objectIds[i];
    return object < frame.levelRules.size() ? frame.levelRules[object] : 0u;
  };
  // The frame's rules, 0 first: without rules the draws go as before them.
  std::vector<uint32_t> rules{0u};
  for (size_t i = 0; i < frame.view.draws.size(); ++i) rules.push_back(levelRuleOf(i));
  std::sort(rules.begin(), rules.end());
  rules.erase(std::unique(rules.begin(), rules.end()), rules.end());
  const size_t count = frame.view.draws.size();
  for (const bool alphaTest : {false, true}) {
    const bool reversed = reverseOpaque && !alphaTest;
    for (size_t r = 0; r < rules.size(); ++r) {
      const uint32_t rule = rules[reversed ? rules.size() - 1 - r : r];
      const gpu::Pipeline* bound = nullptr;
      for (size_t n = 0; n < count; ++n) {
        const size_t i = reversed ? count - 1 - n : n;
        const render::DrawItem& draw = draws[frame.view.draws[i]];
        if ((draw.alphaMode == scene::AlphaMode::Mask) != alphaTest || levelRuleOf(i) != rule) continue;
        if (!bound) {
          bound = &pipeline(alphaTest, rule);
          bindDecoupled(ctx, *bound, frame, bindings);
          frame.view.scene.bindGeometry(ctx.cmd());
        }
        if (alphaTest) {
          const VkDescriptorSet set = frame.view.scene.materialSet(draw.material);
          vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, bound->layout(), 1, 1, &set, 0, nullptr);
        }
        render::drawItem(ctx.cmd(), *bound, draw, frame.objectIds[i], indirect, frame.view.draws[i],
                         render::backFacesHidden(frame.view, frame.view.draws[i]));
      }
    }
  }
}

}  // namespace sg::passes
