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
// Writing requests, the fragment shader touches no table of the masks either.
constexpr std::array kRequestBindings{kBindFrame, kBindParams, kBindObjects, kBindShadelInstances, kBindLevelRectTexels};
constexpr std::array kRequestMergeBindings{kBindShadelMasks, kBindMarkRequests};
constexpr std::array kNeighbourBindings{kBindParams,       kBindShadelInstances, kBindLevelRects,
                                        kBindRemap,        kBindOwnedEntries,    kBindShadelMasks,
                                        kBindShadelMaskPairTexels, kBindEntryBlocks};

std::span<const uint32_t> markBindings(bool shadelMasks, bool ownChunkOnly, bool requests = false) {
  if (requests) return kRequestBindings;
  if (ownChunkOnly) return kOwnChunkBindings;
  return shadelMasks ? std::span<const uint32_t>(kMaskBindings) : kBindings;
}
}  // namespace

bool markOwnChunkOnly(int filter, bool shadelMasks) { return shadelMasks && filter != 0; }

bool markRequestsPossible(const DecoupledFrame& frame) {
  return frame.shadelMasks && !frame.baseline && frame.filter == 1 && frame.ownedEntryCount < kMaxRequestEntries;
}

gpu::ComputePipelineDesc shadelMarkRequestsPipeline() {
  return {.shader = {.path = "passes/shadel-mark/shadel_mark_requests.comp"},
          .layout = decoupledLayout(kRequestMergeBindings, false, 4 * sizeof(int32_t))};
}

gpu::ComputePipelineDesc shadelMarkNeighboursPipeline() {
  return {.shader = {.path = "passes/shadel-mark/shadel_mark_neighbours.comp"},
          .layout = decoupledLayout(kNeighbourBindings, false, sizeof(SgEntrySpan))};
}

gpu::GraphicsPipelineDesc shadelMarkPipeline(int filter, bool baseline, bool alphaTest, VkDescriptorSetLayout materialSet,
                                             bool shadelMasks, uint32_t levelRule, bool requests) {
  std::vector<std::pair<std::string, std::string>> defines{filterDefine(filter)};
  if (baseline) defines.emplace_back("SG_MARK_BASELINE", "1");
  if (shadelMasks) defines.emplace_back("SG_SHADEL_MASKS", "1");
  if (markOwnChunkOnly(filter, shadelMasks)) defines.emplace_back("SG_MARK_OWN_CHUNK_ONLY", "1");
  if (requests) defines.emplace_back("SG_MARK_REQUESTS", "1");
  for (auto& define : levelRuleDefines(levelRule)) defines.push_back(std::move(define));
  const std::span<const uint32_t> bindings = markBindings(shadelMasks, markOwnChunkOnly(filter, shadelMasks), requests);
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
          .colorFormats = requests ? std::vector<VkFormat>{VK_FORMAT_R32_UINT} : std::vector<VkFormat>{},
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          // Requests: drawn in the depth pre-pass (render::DepthPassDraws): of
          // fragments tied in depth the opaque ones keep the first, the
          // alpha-tested ones the last, as composite draws them (compositePipeline).
          .depthWrite = requests,
          .depthCompare = requests && !alphaTest ? VK_COMPARE_OP_LESS : VK_COMPARE_OP_LESS_OR_EQUAL};
}

void drawMarkRequests(PassContext& ctx, const DecoupledFrame& frame, VkBuffer indirect) {
  drawDecoupled(ctx, frame, kRequestBindings, indirect, [&](bool alphaTest, uint32_t levelRule) -> const gpu::Pipeline& {
    return ctx.device().pipeline(
        std::string("shadel-mark/requests") + (alphaTest ? "/alpha-test" : "") + levelRuleVariant(levelRule), [&] {
          return shadelMarkPipeline(frame.filter, false, alphaTest, frame.view.scene.materialSetLayout(), true, levelRule,
                                    true);
        });
  }, /*reverseOpaque=*/true);  // composite's order and tie rule (compositePipeline)
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
  frame.markedFilter = frame.filter;
  const bool ownChunkOnly = markOwnChunkOnly(frame.filter, masks);
  if (frame.markRequests.valid() && masks && ownChunkOnly) {
    // The depth pre-pass wrote the requests (drawMarkRequests): their bits into
    // the masks, over the pixels the decoupled draws can cover.
    auto& merge = graph.addPass("shadel-mark-requests", graph::QueueClass::Graphics, graph::PassKind::Compute);
    merge.read(frame.markRequests, graph::Access::StorageRead);
    frame.masks = merge.write(frame.masks, graph::Access::StorageReadWrite);
    merge.execute([frame](PassContext& ctx) {
      const auto& pipeline = ctx.device().pipeline("shadel-mark-requests", [] { return shadelMarkRequestsPipeline(); });
      bindDecoupled(ctx, pipeline, frame, kRequestMergeBindings);
      const VkExtent2D size = ctx.image(frame.markRequests).extent();
      const int32_t rect[4] = {std::max(frame.cover[0], 0), std::max(frame.cover[1], 0),
                               std::min(frame.cover[2], int32_t(size.width)), std::min(frame.cover[3], int32_t(size.height))};
      if (rect[2] <= rect[0] || rect[3] <= rect[1]) return;  // nothing drawn on screen: no request
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof rect, rect);
      // 8x8 threads of 4x4 pixels a workgroup.
      vkCmdDispatch(ctx.cmd(), uint32_t(rect[2] - rect[0] + 31) / 32, uint32_t(rect[3] - rect[1] + 31) / 32, 1);
    });
  } else {
    frame.markRequests = {};
    auto& pass = graph.addPass("shadel-mark", graph::QueueClass::Graphics);
    pass.read(depth, graph::Access::DepthRead);
    render::readSceneGeometry(pass, frame.view);
    // Read through texel views too (shadel_mark.frag), written by atomics;
    // marking the own chunk only, it leaves the occupancy to the neighbours step.
    if (!ownChunkOnly) {
      pass.read(frame.remap, graph::Access::Sampled, graph::ShaderStage::Fragment);
      frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
    }
    if (masks) {
      pass.read(frame.masks, graph::Access::Sampled, graph::ShaderStage::Fragment);
      frame.masks = pass.write(frame.masks, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
    }
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
  }
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
