#include "z_prepass.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

// The opaque draws of `view`, then the `alphaTested` ones, each from command
// `d` of `indirect` when it is set.
void drawDepth(PassContext& ctx, const render::SceneView& view, VkBuffer indirect,
               const std::vector<uint32_t>& alphaTested, OverdrawCounter counter) {
  const auto& pipeline = ctx.device().pipeline("z-prepass", zPrepassPipeline);
  const gpu::DescriptorWrite frame{shader::kBindFrame, gpu::BufferBinding{view.frameUniforms.handle()}};
  ctx.bind(pipeline, {frame});
  view.scene.bindGeometry(ctx.cmd());
  counter.begin(ctx.cmd());
  const auto& draws = view.scene.draws();
  for (uint32_t i : view.draws)
    if (draws[i].alphaMode == scene::AlphaMode::Opaque)
      render::drawItem(ctx.cmd(), pipeline, draws[i], i, indirect, i, render::backFacesHidden(view, i));
  if (alphaTested.empty()) return counter.end(ctx.cmd());
  const auto& tested = ctx.device().pipeline(
      "z-prepass/alpha-test", [&] { return zPrepassAlphaTestPipeline(view.scene.materialSetLayout()); });
  ctx.bind(tested, {frame});
  for (uint32_t i : alphaTested) {
    const VkDescriptorSet set = view.scene.materialSet(draws[i].material);
    vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, tested.layout(), 1, 1, &set, 0, nullptr);
    render::drawItem(ctx.cmd(), tested, draws[i], i, indirect, i, render::backFacesHidden(view, i));
  }
  counter.end(ctx.cmd());
}

}  // namespace

gpu::GraphicsPipelineDesc zPrepassPipeline() {
  return {.vertex = {.path = "passes/z-prepass/z_prepass.vert"},
          .layout = {.bindings = {{shader::kBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                     .pushConstantBytes = sizeof(render::ObjectConstants)},
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = true};
}

gpu::GraphicsPipelineDesc zPrepassAlphaTestPipeline(VkDescriptorSetLayout materialSet) {
  gpu::GraphicsPipelineDesc desc = zPrepassPipeline();
  desc.vertex.defines = {{"SG_ALPHA_TEST", "1"}};
  desc.fragment = {.path = "passes/z-prepass/z_prepass_alpha_test.frag"};
  desc.layout.extraSets = {materialSet};
  return desc;
}

graph::ResourceHandle addZPrepass(graph::RenderGraph& graph, const render::SceneView& view, graph::ResourceHandle depth,
                                  std::vector<uint32_t> alphaTested, OverdrawCounter counter) {
  auto& pass = graph.addPass("z-prepass", graph::QueueClass::Graphics);
  depth = pass.write(depth, graph::Access::DepthAttachment);
  render::readSceneGeometry(pass, view);
  pass.execute([view = render::readDrawCommands(pass, view), depth, alphaTested = std::move(alphaTested),
                counter](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{depth, 1.0f}, true);
    drawDepth(ctx, view, view.indirect, alphaTested, counter);
    ctx.endRendering();
  });
  return depth;
}

graph::ResourceHandle addZPrepassLate(graph::RenderGraph& graph, const render::SceneView& view,
                                      graph::ResourceHandle depth, graph::ResourceHandle late,
                                      std::vector<uint32_t> alphaTested, OverdrawCounter counter) {
  auto& pass = graph.addPass("z-prepass (late)", graph::QueueClass::Graphics);
  pass.read(late, graph::Access::IndirectArgs);
  render::readSceneGeometry(pass, view);
  depth = pass.write(depth, graph::Access::DepthAttachment);
  pass.execute([view, depth, late, alphaTested = std::move(alphaTested), counter](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{depth, {}}, true);
    drawDepth(ctx, view, ctx.buffer(late).handle(), alphaTested, counter);
    ctx.endRendering();
  });
  return depth;
}

}  // namespace sg::passes
