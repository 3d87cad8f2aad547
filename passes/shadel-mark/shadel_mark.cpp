#include "shadel_mark.hpp"

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr uint32_t kChunkSlotsPerEntry = 64;  // chunk slots per owned entry, one mask each
constexpr std::array kBindings{kBindFrame,       kBindParams,      kBindObjects,        kBindShadelInstances,
                               kBindLevelRects,  kBindRemap,       kBindRemapTexels,    kBindLevelRectTexels};
// The level rectangles as a storage buffer only for the baseline (sgLevelRect),
// which has no masks.
constexpr std::array kMaskBindings{kBindFrame,       kBindParams,           kBindObjects, kBindShadelInstances,
                                   kBindRemap,       kBindRemapTexels,      kBindLevelRectTexels,
                                   kBindShadelMasks, kBindShadelMaskTexels};
// Marking the own chunk's mask only, the fragment shader leaves the remap
// entry (its occupancy) to shadel-mark-neighbours.
constexpr std::array kOwnChunkBindings{kBindFrame,           kBindParams,      kBindObjects, kBindShadelInstances,
                                       kBindLevelRectTexels, kBindShadelMasks, kBindShadelMaskTexels};
constexpr std::array kNeighbourBindings{kBindParams,       kBindShadelInstances, kBindLevelRects,
                                        kBindRemap,        kBindOwnedEntries,    kBindShadelMasks,
                                        kBindShadelMaskPairTexels, kBindEntryBlocks};

std::span<const uint32_t> markBindings(bool shadelMasks, bool ownChunkOnly) {
  if (ownChunkOnly) return kOwnChunkBindings;
  return shadelMasks ? std::span<const uint32_t>(kMaskBindings) : kBindings;
}
}  // namespace

bool markOwnChunkOnly(int filter, bool shadelMasks) { return shadelMasks && filter != 0; }

gpu::ComputePipelineDesc shadelMarkNeighboursPipeline() {
  return {.shader = {.path = "passes/shadel-mark/shadel_mark_neighbours.comp"},
          .layout = decoupledLayout(kNeighbourBindings, false, sizeof(SgEntrySpan))};
}

gpu::GraphicsPipelineDesc shadelMarkPipeline(int filter, bool baseline, bool alphaTest, VkDescriptorSetLayout materialSet,
                                             bool shadelMasks, uint32_t levelRule) {
  std::vector<std::pair<std::string, std::string>> defines{filterDefine(filter)};
  if (baseline) defines.emplace_back("SG_MARK_BASELINE", "1");
  if (shadelMasks) defines.emplace_back("SG_SHADEL_MASKS", "1");
  if (markOwnChunkOnly(filter, shadelMasks)) defines.emplace_back("SG_MARK_OWN_CHUNK_ONLY", "1");
  for (auto& define : levelRuleDefines(levelRule)) defines.push_back(std::move(define));
  const std::span<const uint32_t> bindings = markBindings(shadelMasks, markOwnChunkOnly(filter, shadelMasks));
  std::vector<std::pair<std::string, std::string>> vertexDefines;
  if (baseline) vertexDefines.emplace_back("SG_MARK_BASELINE", "1");  // the baseline reads its levels itself
  if (alphaTest) {
    defines.emplace_back("SG_ALPHA_TEST", "1");
    vertexDefines.emplace_back("SG_ALPHA_TEST", "1");
  }
  return {.vertex = {.path = "passes/shadel-mark/shadel_mark.vert", .defines = vertexDefines},
          .fragment = {.path = "passes/shadel-mark/shadel_mark.frag", .defines = defines},
          .layout = alphaTest ? decoupledLayout(bindings, false, sizeof(render::ObjectConstants), {materialSet})
                              : decoupledLayout(bindings, false, sizeof(render::ObjectConstants)),
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = false};
}

void addShadelMark(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle depth) {
  const bool masks = frame.shadelMasks && !frame.baseline;
  if (masks) {
    // One 64-bit mask per chunk slot (64 per owned entry), zeroed every frame
    // in the live spans (only their entries are marked and shaded).
    frame.masks = graph.createBuffer(
        "shadel masks", {.size = sizeof(uint64_t) * kChunkSlotsPerEntry * std::max(frame.ownedEntryCount, 1u)});
    auto& clear = graph.addPass("shadel-mask-clear", graph::QueueClass::Graphics, graph::PassKind::Transfer);
    frame.masks = clear.write(frame.masks, graph::Access::TransferDst);
    clear.execute([buffer = frame.masks, spans = frame.liveSpans](PassContext& ctx) {
      constexpr VkDeviceSize kEntryBytes = sizeof(uint64_t) * kChunkSlotsPerEntry;
      for (const SgEntrySpan& span : spans)
        if (span.end > span.begin)
          vkCmdFillBuffer(ctx.cmd(), ctx.buffer(buffer).handle(), kEntryBytes * span.begin,
                          kEntryBytes * (span.end - span.begin), 0);
    });
  } else {
    frame.masks = {};
  }
  auto& pass = graph.addPass("shadel-mark", graph::QueueClass::Graphics);
  pass.read(depth, graph::Access::DepthRead);
  render::readSceneGeometry(pass, frame.view);
  // Read through texel views too (shadel_mark.frag), written by atomics;
  // marking the own chunk only, it leaves the occupancy to the neighbours step.
  const bool ownChunkOnly = markOwnChunkOnly(frame.filter, masks);
  if (!ownChunkOnly) {
    pass.read(frame.remap, graph::Access::Sampled, graph::ShaderStage::Fragment);
    frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
  }
  if (masks) {
    pass.read(frame.masks, graph::Access::Sampled, graph::ShaderStage::Fragment);
    frame.masks = pass.write(frame.masks, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
  }
  frame.markedFilter = frame.filter;
  // Culled draws (instance count 0 in the frame's draw commands) are skipped.
  pass.execute([indirect = render::readDrawCommands(pass, frame.view).indirect, frame, depth, masks,
                ownChunkOnly](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{depth, {}, true}, true);
    const std::span<const uint32_t> bindings = markBindings(masks, ownChunkOnly);
    drawDecoupled(ctx, frame, bindings, indirect, [&](bool alphaTest, uint32_t levelRule) -> const gpu::Pipeline& {
      const std::string variant = std::to_string(frame.filter) + (frame.baseline ? "/baseline" : "") +
                                  (alphaTest ? "/alpha-test" : "") + (masks ? "/masks" : "") +
                                  levelRuleVariant(levelRule);
      return ctx.device().pipeline("shadel-mark/" + variant, [&] {
        return shadelMarkPipeline(frame.filter, frame.baseline, alphaTest, frame.view.scene.materialSetLayout(), masks,
                                  levelRule);
      });
    });
    ctx.endRendering();
  });
  if (!ownChunkOnly) return;
  // The marked chunks' occupancy bits, and the gutters' shadels in the neighbours of the marked chunks.
  auto& neighbours = graph.addPass("shadel-mark-neighbours", graph::QueueClass::Graphics, graph::PassKind::Compute);
  frame.remap = neighbours.write(frame.remap, graph::Access::StorageReadWrite);
  neighbours.read(frame.masks, graph::Access::Sampled);
  frame.masks = neighbours.write(frame.masks, graph::Access::StorageReadWrite);
  readEntryBlocks(neighbours, frame);
  neighbours.execute([frame](PassContext& ctx) {
    const auto& pipeline =
        ctx.device().pipeline("shadel-mark-neighbours", [] { return shadelMarkNeighboursPipeline(); });
    bindDecoupled(ctx, pipeline, frame, kNeighbourBindings);
    dispatchEntrySpans(ctx, pipeline, frame);
  });
}

}  // namespace sg::passes
