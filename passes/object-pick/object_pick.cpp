#include "object_pick.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

#include "object_pick_interface.h"

namespace sg::passes {
namespace {

struct PickPush {
  render::ObjectConstants object;
  shader::SgPickWindow window;
};

}  // namespace

gpu::GraphicsPipelineDesc objectPickPipeline() {
  return {.vertex = {.path = "passes/object-pick/object_pick.vert"},
          .fragment = {.path = "passes/object-pick/object_pick.frag"},
          .layout = {.bindings = {{shader::kBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                     .pushConstantBytes = sizeof(PickPush)},
          .vertexInput = render::sceneVertexInput(),
          .colorFormats = {VK_FORMAT_R32_UINT},
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = true};
}

gpu::GraphicsPipelineDesc objectPickAlphaTestPipeline(VkDescriptorSetLayout materialSet) {
  gpu::GraphicsPipelineDesc desc = objectPickPipeline();
  desc.vertex.defines = {{"SG_ALPHA_TEST", "1"}};
  desc.fragment.defines = {{"SG_ALPHA_TEST", "1"}};
  desc.layout.extraSets = {materialSet};
  return desc;
}

graph::ResourceHandle addObjectPick(graph::RenderGraph& graph, const render::SceneView& view, glm::uvec2 pixel,
                                    glm::uvec2 size, graph::ResourceHandle result) {
  auto id = graph.createImage("pick id", {.format = graph::Format::R32Uint, .size = graph::Size::absolute(1, 1)});
  auto depth = graph.createImage("pick depth", {.format = graph::Format::D32F, .size = graph::Size::absolute(1, 1)});
  auto& raster = graph.addPass("object-pick", graph::QueueClass::Graphics);
  id = raster.write(id, graph::Access::ColorAttachment);
  depth = raster.write(depth, graph::Access::DepthAttachment);
  render::readSceneGeometry(raster, view);
  // The clicked pixel's centre in clip space (+y up, as the scene cameras' viewport flips it).
  const shader::SgPickWindow window{
      {(float(pixel.x) + 0.5f) / float(size.x) * 2.0f - 1.0f, 1.0f - (float(pixel.y) + 0.5f) / float(size.y) * 2.0f},
      glm::vec2(size)};
  raster.execute([&scene = view.scene, &uniforms = view.frameUniforms,
                  draws = std::vector<uint32_t>(view.draws.begin(), view.draws.end()), id, depth, window](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("object-pick", objectPickPipeline);
    const gpu::DescriptorWrite frame{shader::kBindFrame, gpu::BufferBinding{uniforms.handle()}};
    const auto bind = [&](const gpu::Pipeline& p) {
      ctx.bind(p, {frame});
      vkCmdPushConstants(ctx.cmd(), p.layout(), VK_SHADER_STAGE_ALL, offsetof(PickPush, window), sizeof window, &window);
    };
    ctx.beginRendering({ColorTarget{id, VkClearColorValue{}}}, DepthTarget{depth, 1.0f}, true);
    bind(pipeline);
    scene.bindGeometry(ctx.cmd());
    // Every draw, occlusion-culled or not: the depth test finds the nearest;
    // blended ones count as opaque (a click on glass picks the glass).
    std::vector<uint32_t> masked;
    for (const uint32_t d : draws) {
      if (scene.draws()[d].alphaMode == scene::AlphaMode::Mask)
        masked.push_back(d);
      else
        render::drawItem(ctx.cmd(), pipeline, scene.draws()[d], scene.draws()[d].instance + 1);
    }
    if (!masked.empty()) {
      const auto& tested = ctx.device().pipeline(
          "object-pick/alpha-test", [&] { return objectPickAlphaTestPipeline(scene.materialSetLayout()); });
      bind(tested);
      for (const uint32_t d : masked) {
        const VkDescriptorSet set = scene.materialSet(scene.draws()[d].material);
        vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, tested.layout(), 1, 1, &set, 0, nullptr);
        render::drawItem(ctx.cmd(), tested, scene.draws()[d], scene.draws()[d].instance + 1);
      }
    }
    ctx.endRendering();
  });
  auto& copy = graph.addPass("object-pick readback", graph::QueueClass::Graphics, graph::PassKind::Transfer);
  copy.read(id, graph::Access::TransferSrc);
  result = copy.write(result, graph::Access::TransferDst);
  copy.execute([id, result](PassContext& ctx) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {1, 1, 1};
    vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(id).handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           ctx.buffer(result).handle(), 1, &region);
  });
  return result;
}

}  // namespace sg::passes
