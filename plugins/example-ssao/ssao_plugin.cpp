// example-ssao: a pass before shading whose output a material layer samples.
// "ssao" estimates ambient occlusion from the depth buffer into the frame
// resource "ao.image"; the layer "ao-darken" samples it (in both the
// decoupled and the forward variant, at the surface's screen position) and
// darkens the glTF PBR result; the frame "ssao" runs the pass right after the
// z-prepass. Written only against the installed shadelgraph package.
#include <filesystem>
#include <string>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/plugin/plugin_api.hpp>
#include <shadelgraph/render/frame_context.hpp>

namespace {

struct SsaoConstants {
  float radius;    // world units
  float strength;  // 0: no darkening, 1: full
};

void declareSsao(sg::render::FrameContext& ctx) {
  const SsaoConstants constants{ctx.parameter<float>("radius"), ctx.parameter<float>("strength")};
  const auto depth = ctx.read("scene.depth");
  auto& graph = ctx.graph();
  auto ao = graph.createImage("ao", {.format = sg::graph::Format::R16F});
  auto& pass = graph.addPass("ssao", sg::graph::QueueClass::Graphics);
  pass.read(depth, sg::graph::Access::Sampled, sg::graph::ShaderStage::Fragment);
  ao = pass.write(ao, sg::graph::Access::ColorAttachment);
  const VkBuffer frameUniforms = ctx.view({}).frameUniforms.handle();
  pass.execute([depth, ao, constants, frameUniforms](sg::PassContext& pc) {
    const auto& pipeline = pc.device().pipeline("example-ssao", [&] {
      return sg::gpu::GraphicsPipelineDesc{
          .vertex = {.path = "framework/render/shaders/fullscreen.vert"},
          .fragment = {.path = "example-ssao/ssao.frag"},
          .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}, {1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}},
                     .pushConstantBytes = sizeof(SsaoConstants)},
          .colorFormats = {VK_FORMAT_R16_SFLOAT}};
    });
    pc.beginRendering({sg::ColorTarget{ao, VkClearColorValue{{1.0f, 1.0f, 1.0f, 1.0f}}}});
    pc.bind(pipeline, {{0, sg::gpu::BufferBinding{frameUniforms}},
                       {1, sg::gpu::ImageBinding{pc.image(depth).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                 pc.device().nearestSampler()}}});
    vkCmdPushConstants(pc.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof constants, &constants);
    vkCmdDraw(pc.cmd(), 3, 1, 0, 0);
    pc.endRendering();
  });
  ctx.write("ao.image", ao);
}

void registerSsao(sg::plugin::Registry* registry, const char* directory) {
  registry->addShaderDirectory(std::filesystem::path(directory) / "shaders");
  registry->addPass({.name = "ssao",
                     .description = "screen-space ambient occlusion from the depth buffer into ao.image",
                     .reads = {"scene.depth"},
                     .writes = {"ao.image"},
                     .parameters = {{"radius", 0.6, "occluder search radius, world units"},
                                    {"strength", 1.0, "how dark full occlusion gets, 0..1"}},
                     .declare = declareSsao});
  registry->addLayer({.name = "ao-darken",
                      .source = "example-ssao/ao_darken.glsl",
                      .function = "aoDarken",
                      .reads = {{.layer = "gltf-pbr"}},
                      .frameInputs = {{.name = "aoImage", .resource = "ao.image"}}});
  registry->addMaterial({.name = "example-ao-pbr", .layers = {"gltf-pbr", "ao-darken"}});
  registry->addFrame({.name = "ssao", .base = "decoupled", .passes = {{.pass = "ssao", .after = {"z-prepass"}}}});
}

}  // namespace

SG_PLUGIN("example-ssao", registerSsao)
