#include "debug_views.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

// A full-screen pass into a new HDR image with the decoupled bindings given.
template <class Push>
graph::ResourceHandle addFullscreenView(graph::RenderGraph& graph, const render::DecoupledFrame& frame,
                                        const char* name, const char* fragment,
                                        std::initializer_list<uint32_t> bindings, const Push& push,
                                        graph::Pass*& passOut) {
  auto view = graph.createImage(std::string(name) + " image", {.format = graph::Format::RGBA16F});
  auto& pass = graph.addPass(name, graph::QueueClass::Graphics);
  view = pass.write(view, graph::Access::ColorAttachment);
  passOut = &pass;
  const std::vector<uint32_t> bindingList(bindings);
  pass.execute([frame, view, name, fragment, bindingList, push](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline(name, [&] {
      const gpu::PipelineLayoutDesc layout = render::decoupledLayout(bindingList, false, sizeof(Push));
      return gpu::GraphicsPipelineDesc{.vertex = {.path = "framework/render/shaders/fullscreen.vert"},
                                       .fragment = {.path = fragment},
                                       .layout = layout,
                                       .colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT}};
    });
    ctx.beginRendering({ColorTarget{view, VkClearColorValue{{0.0f, 0.0f, 0.0f, 1.0f}}}});
    render::bindDecoupled(ctx, pipeline, frame, bindingList);
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
    vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
    ctx.endRendering();
  });
  return view;
}

}  // namespace

graph::ResourceHandle addOccupancyView(graph::RenderGraph& graph, const render::DecoupledFrame& frame,
                                       glm::uvec2 originChunks, glm::uvec2 sizeChunks) {
  using namespace render;
  const glm::uvec4 push{originChunks, sizeChunks};
  graph::Pass* pass = nullptr;
  auto view = addFullscreenView(graph, frame, "debug-occupancy", "passes/debug-views/occupancy.frag",
                                {kBindParams, kBindShadelInstances, kBindLevelRects, kBindRemap, kBindOwnedEntries},
                                push, pass);
  pass->read(frame.remap, graph::Access::StorageRead);
  return view;
}

graph::ResourceHandle addSheetView(graph::RenderGraph& graph, const render::DecoupledFrame& frame) {
  graph::Pass* pass = nullptr;
  auto view = addFullscreenView(graph, frame, "debug-sheet", "passes/debug-views/sheet.frag", {render::kBindLayerImage},
                                uint32_t{0}, pass);
  pass->read(frame.shadedColor, graph::Access::Sampled);
  return view;
}

}  // namespace sg::passes
