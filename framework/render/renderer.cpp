#include <shadelgraph/render/renderer.hpp>

#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/render/frame_uniforms.hpp>

namespace sg::render {

// One frame's declaration: the graph holds callbacks that refer to `view`.
struct Renderer::Frame {
  SceneView view;
  graph::RenderGraph graph;
  graph::ResourceHandle output;
};

Renderer::Renderer(gpu::Device& device, const scene::Scene& scene, FrameRecipe recipe,
                   const plugin::Registry& materials)
    : device_(device),
      scene_(scene),
      recipe_(std::move(recipe)),
      materials_(materials),
      layerTextures_(device, materials),
      gpuScene_(device.context(), device.memory(), scene),
      frameUniforms_(device.context(), device.memory(),
                     {sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryLocation::Upload,
                      "frame uniforms", "frame"}),
      executor_(device) {
  materials_.check();
  for (const auto& draw : gpuScene_.draws())
    if (!materials_.hasMaterial(draw.materialStack))
      throw plugin::PluginError("object '" + scene.instances[draw.instance].name + "' uses material '" +
                                draw.materialStack + "', which no plugin registered");
  // Plugins' GLSL (their layers' sources) by virtual path.
  for (const auto& directory : materials_.shaderDirectories()) device_.shaders().addDirectory(directory);
}

Renderer::~Renderer() = default;

scene::Camera Renderer::camera(const RenderSettings& settings) const {
  if (settings.cameraOverride) return *settings.cameraOverride;
  if (settings.camera >= 0) {
    if (size_t(settings.camera) >= scene_.cameras.size())
      throw std::out_of_range("camera index " + std::to_string(settings.camera) + ": the scene has " +
                              std::to_string(scene_.cameras.size()) + " camera(s)");
    return scene_.cameras[size_t(settings.camera)];
  }
  if (!scene_.cameras.empty()) return scene_.cameras.front();
  return scene::frameBounds(scene::worldBounds(scene_), float(settings.width) / float(settings.height));
}

std::unique_ptr<Renderer::Frame> Renderer::declare(const RenderSettings& settings) {
  const scene::Camera cam = camera(settings);
  const FrameUniforms uniforms = makeFrameUniforms(scene_, cam, settings.width, settings.height);
  frameUniforms_.write(&uniforms, sizeof uniforms);

  if (!output_ || output_->desc().width != settings.width || output_->desc().height != settings.height) {
    vkDeviceWaitIdle(device_.context().device());
    output_.emplace(device_.context(), device_.memory(),
                    gpu::ImageDesc{.width = settings.width, .height = settings.height,
                                   .format = VK_FORMAT_R8G8B8A8_SRGB,
                                   .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   .name = "output", .category = "output"});
  }
  auto frame = std::make_unique<Frame>(Frame{{gpuScene_, frameUniforms_, gpuScene_.allDraws(), materials_, layerTextures_}, {}, {}});
  frame->output = frame->graph.importImage(
      "output", {.format = graph::Format::RGBA8Srgb, .size = graph::Size::absolute(settings.width, settings.height)},
      graph::ImportedState{graph::Layout::Undefined},
      graph::FinalState{graph::Layout::TransferSrc, graph::PipelineStage::Transfer, graph::AccessFlag::TransferRead});
  const float focal = cam.projection == scene::Projection::Perspective
                          ? std::abs(uniforms.projection[1][1]) * 0.5f * float(settings.height)
                          : 0.0f;
  const auto result = recipe_(frame->graph, {frame->view, scene_, device_, executor_, cam.position(), focal,
                                             uniforms.viewProjection, settings.width, settings.height, frame->output});
  frame->graph.markOutput(result);
  return frame;
}

graph::CompiledPlan Renderer::plan(const RenderSettings& settings) {
  auto frame = declare(settings);
  return executor_.compile(frame->graph, {.outputWidth = settings.width, .outputHeight = settings.height,
                                          .enableAliasing = settings.aliasing});
}

FrameResult Renderer::render(const RenderSettings& settings) {
  gpu::CpuTimer timer;
  auto frame = declare(settings);
  const graph::CompiledPlan& plan = executor_.compile(frame->graph, {.outputWidth = settings.width, .outputHeight = settings.height,
                                                      .enableAliasing = settings.aliasing});
  executor_.bindImage(frame->output, *output_);
  FrameResult result;
  result.timings = executor_.execute(frame->graph, plan);
  result.timings.frameMs = timer.elapsedMs();
  result.transientBytes = executor_.transientBytes();
  result.image = gpu::readImage(device_.context(), device_.memory(), *output_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  return result;
}

}  // namespace sg::render
