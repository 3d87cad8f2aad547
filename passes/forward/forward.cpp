#include "forward.hpp"

#include <algorithm>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

constexpr VkFormat kColorFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

const gpu::Pipeline& forwardPipeline(PassContext& ctx, const render::SceneView& view, bool blend) {
  return ctx.device().pipeline(blend ? "forward-blend" : "forward-opaque", [&] {
    return gpu::GraphicsPipelineDesc{
        .vertex = {.path = "passes/forward/forward.vert"},
        .fragment = {.path = "passes/forward/forward.frag"},
        .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                   .extraSets = {view.scene.materialSetLayout()},
                   .pushConstantBytes = sizeof(render::ObjectConstants)},
        .vertexInput = render::sceneVertexInput(),
        .colorFormats = {kColorFormat},
        .depthFormat = VK_FORMAT_D32_SFLOAT,
        .depthTest = true,
        .depthWrite = !blend,
        .alphaBlend = blend};
  });
}

void drawMaterial(PassContext& ctx, const gpu::Pipeline& pipeline, const render::SceneView& view,
                  const render::DrawItem& draw, uint32_t objectId) {
  VkDescriptorSet set = view.scene.materialSet(draw.material);
  vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 1, 1, &set, 0, nullptr);
  render::drawItem(ctx.cmd(), pipeline, draw, objectId);
}

}  // namespace

ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets) {
  auto& pass = graph.addPass("forward-opaque", graph::QueueClass::Graphics);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  targets.depth = pass.write(targets.depth, graph::Access::DepthAttachment);
  pass.execute([view, targets](PassContext& ctx) {
    const auto& pipeline = forwardPipeline(ctx, view, false);
    ctx.beginRendering({ColorTarget{targets.color, VkClearColorValue{{0.42f, 0.55f, 0.75f, 1.0f}}}},
                       DepthTarget{targets.depth}, true);
    ctx.bind(pipeline, {{0, gpu::BufferBinding{view.frameUniforms.handle()}}});
    view.scene.bindGeometry(ctx.cmd());
    const auto& draws = view.scene.draws();
    for (uint32_t i : view.draws)
      if (draws[i].alphaMode != scene::AlphaMode::Blend) drawMaterial(ctx, pipeline, view, draws[i], i);
    ctx.endRendering();
  });
  return targets;
}

graph::ResourceHandle addForwardBlend(graph::RenderGraph& graph, const render::SceneView& view,
                                      const glm::vec3& cameraPosition, ForwardTargets targets) {
  auto& pass = graph.addPass("forward-blend", graph::QueueClass::Graphics);
  pass.read(targets.color, graph::Access::ColorAttachmentRead);  // blends over the opaque result
  pass.read(targets.depth, graph::Access::DepthRead);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  pass.execute([view, targets, cameraPosition](PassContext& ctx) {
    const auto& pipeline = forwardPipeline(ctx, view, true);
    // Back to front by the distance of each object's origin: the usual
    // compromise for per-object sorting (intersecting objects stay wrong).
    std::vector<uint32_t> order;
    const auto& draws = view.scene.draws();
    for (uint32_t i : view.draws)
      if (draws[i].alphaMode == scene::AlphaMode::Blend) order.push_back(i);
    auto distance = [&](uint32_t i) { return glm::distance(glm::vec3(draws[i].world[3]), cameraPosition); };
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return distance(a) > distance(b); });
    ctx.beginRendering({ColorTarget{targets.color}}, DepthTarget{targets.depth, {}, true}, true);
    ctx.bind(pipeline, {{0, gpu::BufferBinding{view.frameUniforms.handle()}}});
    view.scene.bindGeometry(ctx.cmd());
    for (uint32_t i : order) drawMaterial(ctx, pipeline, view, draws[i], i);
    ctx.endRendering();
  });
  return targets.color;
}

}  // namespace sg::passes
