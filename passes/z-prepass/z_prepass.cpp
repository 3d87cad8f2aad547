#include "z_prepass.hpp"

#include <algorithm>
#include <iterator>
#include <optional>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

// The package's draws first when it has some, then the opaque draws of
// `view` it does not draw, then the `alphaTested` ones, each from command `d`
// of `indirect` when it is set.
void drawDepth(PassContext& ctx, const render::SceneView& view, VkBuffer indirect,
               const std::vector<uint32_t>& alphaTested, OverdrawCounter counter,
               const render::DepthPassDraws* package) {
  const auto ownDraw = [&](uint32_t i) {
    return !package || !std::binary_search(package->draws.begin(), package->draws.end(), i);
  };
  const auto& pipeline = package ? ctx.device().pipeline("z-prepass/no-value", zPrepassNoValuePipeline)
                                 : ctx.device().pipeline("z-prepass", zPrepassPipeline);
  const gpu::DescriptorWrite frame{shader::kBindFrame, gpu::BufferBinding{view.frameUniforms.handle()}};
  const auto bindOwn = [&] {
    ctx.bind(pipeline, {frame});
    view.scene.bindGeometry(ctx.cmd());
  };
  // Bound before the counter's query begins: beginning it with no pipeline bound crashed lavapipe (Mesa 22.3).
  bindOwn();
  counter.begin(ctx.cmd());
  if (package) {
    package->draw(ctx, indirect);
    bindOwn();
  }
  const auto& draws = view.scene.draws();
  for (uint32_t i : view.draws)
    if (draws[i].alphaMode == scene::AlphaMode::Opaque && ownDraw(i))
      render::drawItem(ctx.cmd(), pipeline, draws[i], i, indirect, i, render::backFacesHidden(view, i));
  std::vector<uint32_t> tested;
  std::copy_if(alphaTested.begin(), alphaTested.end(), std::back_inserter(tested), ownDraw);
  if (tested.empty()) return counter.end(ctx.cmd());
  const auto& testedPipeline = ctx.device().pipeline(
      "z-prepass/alpha-test", [&] { return zPrepassAlphaTestPipeline(view.scene.materialSetLayout()); });
  ctx.bind(testedPipeline, {frame});
  for (uint32_t i : tested) {
    const VkDescriptorSet set = view.scene.materialSet(draws[i].material);
    vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, testedPipeline.layout(), 1, 1, &set, 0, nullptr);
    render::drawItem(ctx.cmd(), testedPipeline, draws[i], i, indirect, i, render::backFacesHidden(view, i));
  }
  counter.end(ctx.cmd());
}

// The package's target: made by the first pre-pass of the frame, written by each.
graph::ResourceHandle writePackageTarget(graph::RenderGraph& graph, graph::Pass& pass, render::DepthPassDraws* package) {
  if (!package) return {};
  graph::ResourceHandle target = package->target.valid()
                                     ? package->target
                                     : graph.createImage("depth pre-pass values",
                                                         {.format = graph::Format::R32Uint, .size = graph::Size::relative(1.0f)});
  package->target = pass.write(target, graph::Access::ColorAttachment);
  return package->target;
}

void beginDepth(PassContext& ctx, graph::ResourceHandle depth, graph::ResourceHandle target, bool clear) {
  const std::optional<float> depthClear = clear ? std::optional<float>(1.0f) : std::nullopt;
  if (!target.valid()) return ctx.beginRendering({}, DepthTarget{depth, depthClear}, true);
  const std::optional<VkClearColorValue> targetClear =
      clear ? std::optional<VkClearColorValue>(VkClearColorValue{.uint32 = {0, 0, 0, 0}}) : std::nullopt;
  ctx.beginRendering({ColorTarget{target, targetClear}}, DepthTarget{depth, depthClear}, true);
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

gpu::GraphicsPipelineDesc zPrepassNoValuePipeline() {
  gpu::GraphicsPipelineDesc desc = zPrepassPipeline();
  desc.fragment = {.path = "passes/z-prepass/z_prepass_no_value.frag"};
  desc.colorFormats = {VK_FORMAT_R32_UINT};
  desc.depthCompare = VK_COMPARE_OP_LESS;  // a package's fragment tied in depth keeps the pixel
  return desc;
}

gpu::GraphicsPipelineDesc zPrepassAlphaTestPipeline(VkDescriptorSetLayout materialSet) {
  gpu::GraphicsPipelineDesc desc = zPrepassPipeline();
  desc.vertex.defines = {{"SG_ALPHA_TEST", "1"}};
  desc.fragment = {.path = "passes/z-prepass/z_prepass_alpha_test.frag"};
  desc.layout.extraSets = {materialSet};
  return desc;
}

graph::ResourceHandle addZPrepass(graph::RenderGraph& graph, const render::SceneView& view, graph::ResourceHandle depth,
                                  std::vector<uint32_t> alphaTested, OverdrawCounter counter,
                                  render::DepthPassDraws* package) {
  auto& pass = graph.addPass("z-prepass", graph::QueueClass::Graphics);
  depth = pass.write(depth, graph::Access::DepthAttachment);
  const graph::ResourceHandle target = writePackageTarget(graph, pass, package);
  render::readSceneGeometry(pass, view);
  pass.execute([view = render::readDrawCommands(pass, view), depth, target, alphaTested = std::move(alphaTested),
                counter, package = package ? std::optional<render::DepthPassDraws>(*package) : std::nullopt](
                   PassContext& ctx) {
    beginDepth(ctx, depth, target, true);
    drawDepth(ctx, view, view.indirect, alphaTested, counter, package ? &*package : nullptr);
    ctx.endRendering();
  });
  return depth;
}

graph::ResourceHandle addZPrepassLate(graph::RenderGraph& graph, const render::SceneView& view,
                                      graph::ResourceHandle depth, graph::ResourceHandle late,
                                      std::vector<uint32_t> alphaTested, OverdrawCounter counter,
                                      render::DepthPassDraws* package) {
  auto& pass = graph.addPass("z-prepass (late)", graph::QueueClass::Graphics);
  pass.read(late, graph::Access::IndirectArgs);
  render::readSceneGeometry(pass, view);
  depth = pass.write(depth, graph::Access::DepthAttachment);
  const graph::ResourceHandle target = writePackageTarget(graph, pass, package);
  pass.execute([view, depth, late, target, alphaTested = std::move(alphaTested), counter,
                package = package ? std::optional<render::DepthPassDraws>(*package) : std::nullopt](PassContext& ctx) {
    beginDepth(ctx, depth, target, false);
    drawDepth(ctx, view, ctx.buffer(late).handle(), alphaTested, counter, package ? &*package : nullptr);
    ctx.endRendering();
  });
  return depth;
}

}  // namespace sg::passes
