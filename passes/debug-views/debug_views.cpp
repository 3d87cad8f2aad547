#include "debug_views.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

constexpr std::array kOccupancyBindings{kBindParams, kBindShadelInstances, kBindLevelRects, kBindRemap, kBindChunkSlots};
constexpr std::array kSheetBindings{kBindLayerImage};

gpu::GraphicsPipelineDesc fullscreenView(const char* fragment, std::span<const uint32_t> bindings,
                                         uint32_t pushConstantBytes) {
  return {.vertex = {.path = "framework/render/shaders/fullscreen.vert"},
          .fragment = {.path = fragment},
          .layout = decoupledLayout(bindings, false, pushConstantBytes),
          .colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT}};
}

// A full-screen pass into a new HDR image with the decoupled bindings given
// and `push` (when it has a size) as its push constants.
template <size_t N>
graph::ResourceHandle addFullscreenView(graph::RenderGraph& graph, const DecoupledFrame& frame, const char* name,
                                        gpu::GraphicsPipelineDesc (*describe)(),
                                        const std::array<uint32_t, N>& bindings, std::span<const std::byte> push,
                                        graph::Pass*& passOut) {
  auto view = graph.createImage(std::string(name) + " image", {.format = graph::Format::RGBA16F});
  auto& pass = graph.addPass(name, graph::QueueClass::Graphics);
  view = pass.write(view, graph::Access::ColorAttachment);
  passOut = &pass;
  const std::vector<std::byte> pushBytes(push.begin(), push.end());
  pass.execute([frame, view, name, describe, bindings, pushBytes](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline(name, describe);
    ctx.beginRendering({ColorTarget{view, VkClearColorValue{{0.0f, 0.0f, 0.0f, 1.0f}}}});
    bindDecoupled(ctx, pipeline, frame, bindings);
    if (!pushBytes.empty())
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, uint32_t(pushBytes.size()),
                         pushBytes.data());
    vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    ctx.endRendering();
  });
  return view;
}

}  // namespace

gpu::GraphicsPipelineDesc occupancyViewPipeline() {
  return fullscreenView("passes/debug-views/occupancy.frag", kOccupancyBindings, sizeof(SgOccupancyPush));
}

gpu::GraphicsPipelineDesc sheetViewPipeline() { return fullscreenView("passes/debug-views/sheet.frag", kSheetBindings, 0); }

graph::ResourceHandle addOccupancyView(graph::RenderGraph& graph, const DecoupledFrame& frame,
                                       glm::uvec2 originChunks, glm::uvec2 sizeChunks) {
  const SgOccupancyPush push{originChunks, sizeChunks};
  graph::Pass* pass = nullptr;
  auto view = addFullscreenView(graph, frame, "debug-occupancy", occupancyViewPipeline, kOccupancyBindings,
                                std::as_bytes(std::span(&push, 1)), pass);
  pass->read(frame.remap, graph::Access::StorageRead);
  pass->read(frame.slots, graph::Access::StorageRead);
  return view;
}

graph::ResourceHandle addSheetView(graph::RenderGraph& graph, const DecoupledFrame& frame) {
  graph::Pass* pass = nullptr;
  auto view = addFullscreenView(graph, frame, "debug-sheet", sheetViewPipeline, kSheetBindings, {}, pass);
  pass->read(frame.shadedColor, graph::Access::Sampled);
  return view;
}

}  // namespace sg::passes
