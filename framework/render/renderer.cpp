#include <shadelgraph/render/renderer.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/render/frame_uniforms.hpp>
#include <shadelgraph/render/frustum.hpp>
#include <shadelgraph/render/shaders/light_grid.h>
#include <shadelgraph/scene/bounds.hpp>

namespace sg::render {
namespace {

// The world bounding box of every draw, and the sphere around each (frustum and occlusion culling).
std::vector<scene::Bounds> drawBounds(const scene::Scene& scene, const std::vector<DrawItem>& draws) {
  std::vector<scene::Bounds> bounds;
  for (const auto& draw : draws)
    bounds.push_back(scene::transformBounds(scene.meshes[size_t(scene.instances[draw.instance].mesh)].bounds, draw.world));
  return bounds;
}

std::vector<glm::vec4> drawSpheres(const std::vector<scene::Bounds>& bounds) {
  std::vector<glm::vec4> spheres;
  for (const auto& b : bounds) spheres.emplace_back(b.center(), b.radius());
  return spheres;
}

}  // namespace

// One frame's declaration: the graph holds callbacks that refer to `view`,
// `inputs` and the draw lists in `context`.
struct Renderer::Frame {
  SceneView view;
  FrameInputs inputs;
  graph::RenderGraph graph;
  std::optional<FrameContext> context;
  graph::ResourceHandle output;
  std::optional<DeformationFrame> deformation;
  std::vector<ShadowView> shadows;  // inputs.shadowViews
  std::vector<uint8_t> backFacesHidden;  // view.backFacesHidden
  graph::ResourceHandle pick;       // with a pick pending: the readback as imported
  bool pickAnswered = false;        // a pass wrote it
};

Renderer::Renderer(gpu::Device& device, const scene::Scene& scene, const plugin::Registry& registry,
                   plugin::ResolvedFrame frame)
    : device_(device),
      scene_(scene),
      registry_(registry),
      frame_(std::move(frame)),
      layerTextures_(device, registry),
      gpuScene_(device.context(), device.memory(), scene),
      drawBounds_(drawBounds(scene, gpuScene_.draws())),
      drawSpheres_(drawSpheres(drawBounds_)),
      culling_(device.context(), device.memory(), gpuScene_.draws(), drawSpheres_),
      deformation_(device.context(), device.memory(), scene, gpuScene_.deformation()),
      executor_(device) {
  registry_.check();
  if (scene.lights.size() > kMaxLights)
    throw std::invalid_argument("the scene has " + std::to_string(scene.lights.size()) + " lights; at most " +
                                std::to_string(kMaxLights) + " are supported");
  for (auto& uniforms : frameUniforms_)
    uniforms = gpu::Buffer(device.context(), device.memory(),
                           {sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryLocation::Upload,
                            "frame uniforms", "frame"});
  // Sized for the scene's lights (at least the default sun).
  const size_t lightBytes = std::max<size_t>(scene.lights.size(), 1) * sizeof(GpuLight);
  for (auto& lights : lights_)
    lights = gpu::Buffer(device.context(), device.memory(),
                         {lightBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Upload, "lights", "frame"});
  const shader::SgLightGridHeader noGrid{};
  noLightGrid_ = gpu::Buffer(device.context(), device.memory(),
                             {sizeof noGrid + sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                              gpu::MemoryLocation::Upload, "no light grid", "frame"});
  noLightGrid_.write(&noGrid, sizeof noGrid);
  for (const auto& instance : scene.instances) modes_.push_back(instance.shading);
  for (const auto& draw : gpuScene_.draws())
    if (!registry_.hasMaterial(draw.materialStack))
      throw plugin::PluginError("object '" + scene.instances[draw.instance].name + "' uses material '" +
                                draw.materialStack + "', which no plugin registered");
  for (uint32_t i = 0; i < scene.instances.size(); ++i)
    if (deformation_.deformed(i)) updateSpheres(i, scene.instances[i].world);
  // Plugins' GLSL (their layers' sources) by virtual path.
  for (const auto& directory : registry_.shaderDirectories()) device_.shaders().addDirectory(directory);
}

Renderer::~Renderer() = default;

void Renderer::setObjectMode(uint32_t instance, scene::ShadingMode mode) {
  if (instance >= modes_.size())
    throw std::out_of_range("object " + std::to_string(instance) + ": the scene has " + std::to_string(modes_.size()) +
                            " objects");
  modes_[instance] = mode;
}

void Renderer::setObjectTransform(uint32_t instance, const glm::mat4& world) {
  setObjectMode(instance, instance < modes_.size() ? modes_[instance] : scene::ShadingMode::Auto);  // checks the index
  gpuScene_.setInstanceWorld(instance, world);
  deformation_.setWorld(instance, world);
  updateSpheres(instance, world);
}

void Renderer::setObjectDeformation(uint32_t instance, std::span<const glm::mat4> worldJoints,
                                    std::span<const float> weights) {
  setObjectMode(instance, instance < modes_.size() ? modes_[instance] : scene::ShadingMode::Auto);  // checks the index
  deformation_.set(instance, worldJoints, weights);
  const auto& draws = gpuScene_.draws();
  for (uint32_t d = 0; d < draws.size(); ++d)
    if (draws[d].instance == instance) return updateSpheres(instance, draws[d].world);
}

void Renderer::updateSpheres(uint32_t instance, const glm::mat4& world) {
  // A deformed object's vertices move: its sphere holds every joint's box moved by the joint (object_deformation.hpp).
  const auto local = deformation_.deformed(instance) ? deformation_.meshBounds(instance)
                                                     : scene_.meshes[size_t(scene_.instances[instance].mesh)].bounds;
  const auto bounds = scene::transformBounds(local, world);
  const auto& draws = gpuScene_.draws();
  for (uint32_t d = 0; d < draws.size(); ++d) {
    if (draws[d].instance != instance) continue;
    drawBounds_[d] = bounds;
    drawSpheres_[d] = glm::vec4(bounds.center(), bounds.radius());
    culling_.setSphere(d, drawSpheres_[d]);
  }
}

void Renderer::setObjectMaterial(uint32_t instance, const std::string& materialStack) {
  setObjectMode(instance, instance < modes_.size() ? modes_[instance] : scene::ShadingMode::Auto);  // checks the index
  if (!registry_.hasMaterial(materialStack))
    throw plugin::PluginError("object '" + scene_.instances[instance].name + "': material '" + materialStack +
                              "' is not registered");
  gpuScene_.setInstanceMaterialStack(instance, materialStack);
}

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
  const float aspect = float(settings.width) / float(settings.height);
  const auto lights = std::span(scene_.lights).first(std::min<size_t>(scene_.lights.size(), kMaxLights));
  std::vector<ShadowView> shadows =
      shadowViews(lights, drawSpheres_, {cam.view(), cam.projectionMatrix(aspect), cam.znear, cam.zfar});
  const FrameUniforms uniforms = makeFrameUniforms(scene_, cam, settings.width, settings.height, frameLights_, shadows);
  const auto slot = uint32_t(frameNumber_ % 2);
  gpu::Buffer& uniformBuffer = frameUniforms_[slot];
  uniformBuffer.write(&uniforms, sizeof uniforms);
  gpu::Buffer& lightBuffer = lights_[slot];
  lightBuffer.write(frameLights_.data(), frameLights_.size() * sizeof(GpuLight));

  if (!output_ || output_->desc().width != settings.width || output_->desc().height != settings.height) {
    vkDeviceWaitIdle(device_.context().device());
    output_.emplace(device_.context(), device_.memory(),
                    gpu::ImageDesc{.width = settings.width, .height = settings.height,
                                   .format = VK_FORMAT_R8G8B8A8_SRGB,
                                   .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   .name = "output", .category = "output"});
  }
  const float focal = cam.projection == scene::Projection::Perspective
                          ? std::abs(uniforms.projection[1][1]) * 0.5f * float(settings.height)
                          : 0.0f;
  // Built in place (make_unique would move a temporary Frame, and GCC 12 then warns that the moved map
  // may be uninitialized: a false positive).
  auto frame = std::unique_ptr<Frame>(new Frame{
      {gpuScene_, uniformBuffer, lightBuffer, noLightGrid_, gpuScene_.allDraws(), registry_, layerTextures_},
      {scene_, device_, executor_, modes_, drawSpheres_, drawBounds_, frameNumber_++, cam.position(), focal, uniforms.viewProjection,
       settings.width, settings.height, settings.occlusionCulling ? &culling_ : nullptr},
      {}, {}, {}, {}, std::move(shadows)});
  frame->inputs.shadowViews = frame->shadows;
  frame->inputs.zPrepass = settings.zPrepass;
  // Closed surfaces wholly beyond the near plane: the camera is outside, and clipping cannot open them.
  const auto& draws = gpuScene_.draws();
  frame->backFacesHidden.resize(draws.size());
  for (uint32_t d = 0; d < draws.size(); ++d)
    frame->backFacesHidden[d] = draws[d].closedSurface && sphereBeyondNearPlane(uniforms.viewProjection, drawSpheres_[d]);
  frame->view.backFacesHidden = frame->backFacesHidden;
  frame->inputs.pick = settings.pick;
  frame->output = frame->graph.importImage(
      "output", {.format = graph::Format::RGBA8Srgb, .size = graph::Size::absolute(settings.width, settings.height)},
      graph::ImportedState{graph::Layout::Undefined},
      graph::FinalState{graph::Layout::TransferSrc, graph::PipelineStage::Transfer, graph::AccessFlag::TransferRead});
  if (!gpuScene_.deformation().empty()) {
    frame->deformation.emplace(deformation_.write(slot));
    frame->inputs.deformation = &*frame->deformation;
  }
  FrameContext& context = frame->context.emplace(frame->graph, frame->inputs, frame->view, states_, &frame_);
  for (uint32_t d = 0; d < drawSpheres_.size(); ++d)
    if (sphereInFrustum(uniforms.viewProjection, drawSpheres_[d])) context.draws().forward.push_back(d);
  context.write(plugin::kOutputResource, frame->output);
  if (settings.pick) importPick(*frame, *settings.pick, settings.width, settings.height);
  // Packages first settle what they take (prepare), then every pass declares.
  for (const auto& pass : frame_.passes)
    if (pass.pass->prepare) {
      context.setPass(&pass);
      pass.pass->prepare(context);
    }
  for (const auto& pass : frame_.passes) {
    context.setPass(&pass);
    pass.pass->declare(context);
  }
  context.setPass(nullptr);
  const auto result = context.read(plugin::kOutputResource);
  if (result == frame->output)
    throw plugin::FrameError("frame '" + frame_.name + "' writes nothing to '" + plugin::kOutputResource +
                             "' (it needs a pass such as tonemap)");
  frame->graph.markOutput(result);
  if (frame->pick.valid()) {
    const auto picked = context.read(plugin::kPickResource);
    frame->pickAnswered = picked != frame->pick;
    if (frame->pickAnswered) frame->graph.markOutput(picked);
  }
  return frame;
}

// The pick resource of this frame: the readback buffer, cleared to "nothing".
void Renderer::importPick(Frame& frame, glm::uvec2 pixel, uint32_t width, uint32_t height) {
  if (pixel.x >= width || pixel.y >= height)
    throw std::out_of_range("pick pixel " + std::to_string(pixel.x) + "," + std::to_string(pixel.y) +
                            " is outside the " + std::to_string(width) + "x" + std::to_string(height) + " frame");
  if (!pickReadback_)
    pickReadback_ = gpu::Buffer(device_.context(), device_.memory(),
                                {sizeof(uint32_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryLocation::Readback,
                                 "pick readback", "readback"});
  const uint32_t none = 0;
  pickReadback_.write(&none, sizeof none);
  frame.pick = frame.graph.importBuffer("pick readback", {.size = sizeof(uint32_t)}, {},
                                        {graph::Layout::Undefined, graph::PipelineStage::AllCommands,
                                         graph::AccessFlag::None});
  executor_.bindBuffer(frame.pick, pickReadback_);
  frame.context->write(plugin::kPickResource, frame.pick);
}

graph::CompiledPlan Renderer::plan(const RenderSettings& settings) {
  auto frame = declare(settings);
  return executor_.compile(frame->graph, {.outputWidth = settings.width, .outputHeight = settings.height,
                                          .enableAliasing = settings.aliasing});
}

FrameResult Renderer::render(const RenderSettings& settings) {
  gpu::CpuTimer timer;
  executor_.setFramesInFlight(settings.framesInFlight);
  executor_.beginFrame();  // the host-written buffers of this frame's slot are free
  if (settings.time)
    for (uint32_t i = 0; i < scene_.instances.size(); ++i)
      if (scene_.instances[i].motion.moves())
        setObjectTransform(i, scene::movedWorld(scene_.instances[i].motion, scene_.instances[i].world, *settings.time));
  auto frame = declare(settings);
  const graph::CompiledPlan& plan = executor_.compile(frame->graph, {.outputWidth = settings.width, .outputHeight = settings.height,
                                                      .enableAliasing = settings.aliasing});
  executor_.bindImage(frame->output, *output_);
  FrameResult result;
  result.planReused = executor_.reusedLastPlan();
  if (settings.keepPlan) result.plan = plan;
  result.timings = executor_.execute(frame->graph, plan);
  result.timings.frameMs = timer.elapsedMs();
  result.transientBytes = executor_.transientBytes();
  if (frame->pickAnswered) {  // execute waited for the frame
    result.pickAnswered = true;
    uint32_t id = 0;
    std::memcpy(&id, pickReadback_.mapped(), sizeof id);
    if (id != 0) result.picked = id - 1;
  }
  if (settings.readback) result.image = gpu::readImage(device_.context(), device_.memory(), *output_, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  return result;
}

std::vector<gpu::FrameTimings> Renderer::finishFrames() {
  executor_.finish();
  return executor_.takeCompletedTails();
}

}  // namespace sg::render
