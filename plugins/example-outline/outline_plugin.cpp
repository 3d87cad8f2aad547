// example-outline: a pass after tonemap that darkens depth discontinuities of
// the final image, and the frame "outlined" (the decoupled frame plus it).
// Written only against the installed shadelgraph package.
#include <filesystem>
#include <string>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/plugin/plugin_api.hpp>
#include <shadelgraph/render/frame_context.hpp>

namespace {

struct OutlineConstants {
  float strength;
  float threshold;
};

void declareOutline(sg::render::FrameContext& ctx) {
  const OutlineConstants constants{ctx.parameter<float>("strength"), ctx.parameter<float>("threshold")};
  const auto depth = ctx.read("scene.depth");
  auto& pass = ctx.graph().addPass("outline", sg::graph::QueueClass::Graphics);
  pass.read(depth, sg::graph::Access::Sampled, sg::graph::ShaderStage::Fragment);
  const auto output = pass.write(ctx.read("scene.ldr"), sg::graph::Access::ColorAttachment);
  pass.execute([depth, output, constants](sg::PassContext& pc) {
    const VkFormat format = pc.image(output).desc().format;
    const auto& pipeline = pc.device().pipeline("example-outline/" + std::to_string(format), [&] {
      return sg::gpu::GraphicsPipelineDesc{
          .vertex = {.path = "framework/render/shaders/fullscreen.vert"},
          .fragment = {.path = "example-outline/outline.frag"},
          .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}},
                     .pushConstantBytes = sizeof(OutlineConstants)},
          .colorFormats = {format},
          .alphaBlend = true};
    });
    pc.beginRendering({sg::ColorTarget{output}});  // load: draw over the tonemapped image
    pc.bind(pipeline, {{0, sg::gpu::ImageBinding{pc.image(depth).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                 pc.device().nearestSampler()}}});
    vkCmdPushConstants(pc.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof constants, &constants);
    vkCmdDraw(pc.cmd(), 3, 1, 0, 0);
    pc.endRendering();
  });
  ctx.write("scene.ldr", output);
}

void registerOutline(sg::plugin::Registry* registry, const char* directory) {
  registry->addShaderDirectory(std::filesystem::path(directory) / "shaders");
  registry->addPass({.name = "outline",
                     .description = "darkens depth discontinuities over the final image",
                     .reads = {"scene.depth", "scene.ldr"},
                     .writes = {"scene.ldr"},
                     .parameters = {{"strength", 0.85, "opacity of the outline, 0..1"},
                                    {"threshold", 0.002, "depth Laplacian (relative to 1 - depth) that counts as an edge"}},
                     .declare = declareOutline});
  registry->addFrame({.name = "outlined", .base = "decoupled", .passes = {{.pass = "outline", .after = {"tonemap"}}}});
}

}  // namespace

SG_PLUGIN("example-outline", registerOutline)
