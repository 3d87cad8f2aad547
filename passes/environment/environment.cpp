#include "environment.hpp"

#include <algorithm>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_to_vulkan.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/environment_binding.hpp>

#include "environment_maps.hpp"

namespace sg::passes {
namespace {

// Where the maps rest between frames: written as storage once, sampled after.
const graph::ResourceState kResting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                    graph::AccessFlag::ShaderStorageRead | graph::AccessFlag::ShaderStorageWrite |
                                        graph::AccessFlag::ShaderSampledRead};

gpu::Image mapImage(gpu::Device& device, uint32_t width, uint32_t height, const char* name) {
  return gpu::Image(device.context(), device.memory(),
                    {.width = width, .height = height, .format = VK_FORMAT_R32G32B32A32_SFLOAT,
                     .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                     .concurrent = true,  // graphics (forward) and async compute (layer-shade) both read it
                     .name = name, .category = "environment"});
}

void create(EnvironmentMaps& maps, gpu::Device& device, const scene::Environment& env) {
  const uint64_t bytes = env.rgba.size() * sizeof(float);
  maps.source = gpu::Buffer(device.context(), device.memory(),
                            {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Upload,
                             "environment image", "environment", true});
  maps.source.write(env.rgba.data(), bytes);
  using shader::kEnvSpecularWidth;
  // The levels stacked, then a quarter width of rows for level 0's halvings.
  maps.specular = mapImage(device, kEnvSpecularWidth,
                           kEnvSpecularWidth / 2 * shader::kEnvSpecularLevels + kEnvSpecularWidth / 4,
                           "environment specular");
  maps.irradiance = mapImage(device, shader::kEnvIrradianceWidth, shader::kEnvIrradianceWidth / 2,
                             "environment irradiance");
  maps.brdf = mapImage(device, shader::kEnvBrdfSize, shader::kEnvBrdfSize, "environment brdf");
  // The graph expects them resting in General.
  device.context().submitAndWait([&](VkCommandBuffer cmd) {
    for (const gpu::Image* image : {&maps.specular, &maps.irradiance, &maps.brdf})
      gpu::imageBarrier(cmd, image->handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, {},
                        {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT});
  });
  maps.scene = &env;
  maps.prefiltered = false;
}

graph::ResourceHandle importMap(render::FrameContext& frame, const gpu::Image& image, const char* name) {
  const graph::ImageDesc desc{.format = graph::Format::RGBA32F,
                              .size = graph::Size::absolute(image.desc().width, image.desc().height)};
  const auto handle = frame.graph().importPersistentImage(name, desc, kResting);
  frame.inputs().executor.bindImage(handle, image);
  return handle;
}

struct Handles {
  graph::ResourceHandle source, specular, irradiance, brdf;
};


// `irradiance` and `brdf` are what the step's pass binds at those slots: a pass
// binds only images it declares, so a slot its steps leave alone gets one of them.
void dispatch(PassContext& ctx, graph::ResourceHandle source, graph::ResourceHandle specular,
              graph::ResourceHandle irradiance, graph::ResourceHandle brdf, shader::SgEnvironmentPush push,
              uint32_t width, uint32_t height) {
  const auto& pipeline = ctx.device().pipeline("environment-prefilter", environmentPrefilterPipeline);
  const auto storage = [&](uint32_t binding, graph::ResourceHandle image) {
    return gpu::DescriptorWrite{binding, gpu::ImageBinding{ctx.image(image).view(), VK_IMAGE_LAYOUT_GENERAL, VK_NULL_HANDLE}};
  };
  ctx.bind(pipeline, {{shader::kBindEnvSource, gpu::BufferBinding{ctx.buffer(source).handle()}},
                      storage(shader::kBindEnvSpecularOut, specular), storage(shader::kBindEnvIrradianceOut, irradiance),
                      storage(shader::kBindEnvBrdfOut, brdf)});
  vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
  vkCmdDispatch(ctx.cmd(), (width + 7) / 8, (height + 7) / 8, 1);
}

}  // namespace

gpu::ComputePipelineDesc environmentPrefilterPipeline() {
  return {.shader = {.path = "passes/environment/environment_prefilter.comp"},
          .layout = {.bindings = {{shader::kBindEnvSource, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindEnvSpecularOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                  {shader::kBindEnvIrradianceOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                                  {shader::kBindEnvBrdfOut, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}},
                     .pushConstantBytes = sizeof(shader::SgEnvironmentPush)}};
}

EnvironmentMaps& environmentMaps(render::FrameContext& frame) {
  const scene::Environment& env = frame.inputs().scene.environment;
  auto& maps = frame.ownState<EnvironmentMaps>(kEnvironmentMapsState);
  if (maps.scene != &env || !maps.source) create(maps, frame.inputs().device, env);
  return maps;
}

void addEnvironment(render::FrameContext& frame) {
  const scene::Environment& env = frame.inputs().scene.environment;
  if (!env.present()) return;
  auto& maps = environmentMaps(frame);

  Handles h;
  // The image itself, every frame: the prefilter's source once, the background's always.
  h.source = frame.graph().importPersistentBuffer("environment image", {.size = maps.source.size()}, kResting);
  frame.inputs().executor.bindBuffer(h.source, maps.source);
  h.specular = importMap(frame, maps.specular, "environment specular");
  h.irradiance = importMap(frame, maps.irradiance, "environment irradiance");
  h.brdf = importMap(frame, maps.brdf, "environment brdf");
  if (!maps.prefiltered) {
    const uint32_t w = env.width, hgt = env.height;
    const uint32_t level = shader::kEnvSpecularWidth;
    // Level 0 and the BRDF lookup from the image; then what level 0 convolves to.
    auto& down = frame.graph().addPass("environment-downsample", graph::QueueClass::Graphics, graph::PassKind::Compute);
    down.read(h.source, graph::Access::StorageRead);
    h.specular = down.write(h.specular, graph::Access::StorageWrite);
    h.brdf = down.write(h.brdf, graph::Access::StorageWrite);
    down.execute([h, w, hgt, level](PassContext& ctx) {
      // The irradiance slot, untouched by these steps, holds level 0's image.
      // Level 0 and its halvings, each straight from the image (no step reads another's output).
      for (uint32_t k = 0; k <= shader::kEnvPyramidMips; ++k)
        dispatch(ctx, h.source, h.specular, h.specular, h.brdf, {shader::kEnvStepDownsample, k, w, hgt}, level >> k,
                 std::max(level >> (k + 1), 1u));
      dispatch(ctx, h.source, h.specular, h.specular, h.brdf, {shader::kEnvStepBrdf, 0, w, hgt}, shader::kEnvBrdfSize,
               shader::kEnvBrdfSize);
    });
    auto& conv = frame.graph().addPass("environment-prefilter", graph::QueueClass::Graphics, graph::PassKind::Compute);
    conv.read(h.source, graph::Access::StorageRead);
    h.specular = conv.write(h.specular, graph::Access::StorageReadWrite);
    h.irradiance = conv.write(h.irradiance, graph::Access::StorageWrite);
    conv.execute([h, w, hgt, level, done = &maps.prefiltered](PassContext& ctx) {
      // The BRDF slot, untouched by these steps, holds the irradiance image.
      dispatch(ctx, h.source, h.specular, h.irradiance, h.irradiance, {shader::kEnvStepIrradiance, 0, w, hgt},
               shader::kEnvIrradianceWidth, shader::kEnvIrradianceWidth / 2);
      for (uint32_t l = 1; l < shader::kEnvSpecularLevels; ++l)
        dispatch(ctx, h.source, h.specular, h.irradiance, h.irradiance, {shader::kEnvStepSpecular, l, w, hgt}, level,
                 level / 2);
      *done = true;  // recorded: later frames read the maps without prefiltering again
    });
  }
  frame.write(render::kEnvironmentSpecularResource, h.specular);
  frame.write(render::kEnvironmentIrradianceResource, h.irradiance);
  frame.write(render::kEnvironmentBrdfResource, h.brdf);
  frame.write(kEnvironmentImageResource, h.source);
}

}  // namespace sg::passes
