#include "decoupled_shading.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <stdexcept>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/decoupled_frame.hpp>
#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/id_map_cache.hpp>
#include <shadelgraph/shadel/level0_resolution.hpp>
#include <shadelgraph/shadel/shadel_gpu_tables.hpp>

#include "composite/composite.hpp"
#include "debug-views/debug_views.hpp"
#include "exposure/exposure.hpp"
#include "alpha-blend/alpha_blend.hpp"
#include "alpha-mask/alpha_mask.hpp"
#include "forward/forward.hpp"
#include "forward/forward_material.hpp"
#include "layer-shade/layer_shade.hpp"
#include "shadel-allocate/shadel_allocate.hpp"
#include "shadel-clear/shadel_clear.hpp"
#include "shadel-mark/shadel_mark.hpp"
#include "support-expand/support_expand.hpp"
#include "tonemap/tonemap.hpp"
#include "work-aggregate/work_aggregate.hpp"
#include "frustum.hpp"
#include "z-prepass/z_prepass.hpp"

namespace sg::plugins {
namespace {

template <class T>
gpu::Buffer upload(gpu::Device& device, const std::vector<T>& data, const char* name) {
  const size_t bytes = std::max<size_t>(data.size() * sizeof(T), 16);
  gpu::Buffer buffer(device.context(), device.memory(),
                     {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Upload, name, "decoupled tables"});
  if (!data.empty()) buffer.write(data.data(), data.size() * sizeof(T));
  return buffer;
}

}  // namespace

DecoupledShading::DecoupledShading(std::vector<ShadingChoice> choices, DecoupledSettings settings)
    : choices_(std::move(choices)), settings_(settings), adjuster_(settings.adjuster) {
  bias_ = settings_.fixedBias.value_or(adjuster_.bias());
}

DecoupledShading::~DecoupledShading() = default;

render::FrameRecipe DecoupledShading::recipe() {
  return [this](graph::RenderGraph& graph, const render::FrameInputs& inputs) { return declare(graph, inputs); };
}

void DecoupledShading::initialize(const render::FrameInputs& in) {
  gpu::Device& device = in.device;
  const auto& draws = in.view.scene.draws();
  space_ = std::make_unique<shadel::ShadelSpace>(shadel::ShadelSpaceConfig{settings_.sheetSizeLog2});
  shadel::IdMapCache cache;
  std::map<int, std::pair<shadel::DetailLevels, uint32_t>> maps;  // by mesh: its levels and ID-map offset
  std::vector<uint32_t> idTexels;
  std::vector<DecoupledObject> objects;
  const plugin::Registry& materials = in.view.materials;
  for (uint32_t d = 0; d < draws.size(); ++d) {
    ShadingChoice& choice = choices_[draws[d].instance];
    const scene::Mesh& mesh = in.scene.meshes[size_t(in.scene.instances[choice.instance].mesh)];
    const scene::Bounds world = scene::transformBounds(mesh.bounds, draws[d].world);
    drawSpheres_.emplace_back(world.center(), world.radius());
    const plugin::MaterialStack& material = materials.material(draws[d].materialStack);
    if (choice.decoupled && !materials.runsIn(material, plugin::ShadingPath::Decoupled)) {
      choice.decoupled = false;
      choice.reason = "material '" + material.name + "' has forward-only layers";
    }
    if (!choice.decoupled) {
      forwardDraws_.push_back(d);
      continue;
    }
    const int meshIndex = in.scene.instances[choice.instance].mesh;
    auto it = maps.find(meshIndex);
    if (it == maps.end()) {
      const scene::ChartVerdict chart = scene::chooseShadingChart(mesh);
      const uint32_t level0 = shadel::chooseLevel0Size(mesh, chart, shadel::meshTextureDensity(in.scene, mesh));
      auto map = cache.loadOrBake(mesh, chart, {.level0Size = level0});
      const auto offset = uint32_t(idTexels.size());
      idTexels.insert(idTexels.end(), map.texels.begin(), map.texels.end());
      it = maps.emplace(meshIndex, std::pair{map.levels, offset}).first;
    }
    const auto& [levels, offset] = it->second;
    const auto object = uint32_t(objects.size());
    const auto result = space_->allocate(object, levels);
    if (!result.ok()) {
      choice.decoupled = false;
      choice.reason = "no shadel space: " + result.message;
      forwardDraws_.push_back(d);
      continue;
    }
    const auto& draw = draws[d];
    objects.push_back({draw.world, draw.firstIndex, draw.vertexOffset, draw.indexCount / 3, draw.material, offset,
                       uint32_t(choice.uvSet), choice.tileOffset,
                       supportRadius(materials, material) > 0 ? 1u : 0u, {}});
    objectMaterials_.push_back(material.name);
    decoupledDraws_.push_back(d);
    objectAutomatic_.push_back(choice.automatic);
  }
  const auto tables = shadel::buildGpuTables(*space_);
  // The occupancy view shows the square around every allocated level.
  glm::uvec2 lo(~0u), hi(0u);
  for (const auto& rect : tables.levelRects) {
    lo = glm::min(lo, rect.origin / shadel::kChunkSize);
    hi = glm::max(hi, (rect.origin + rect.allocatedSize) / shadel::kChunkSize);
  }
  if (!tables.levelRects.empty()) {
    sheetRegionOrigin_ = lo;
    sheetRegionSize_ = glm::uvec2(std::max(hi.x - lo.x, hi.y - lo.y));
  }
  ownedEntryCount_ = uint32_t(tables.ownedEntries.size());
  idMapBytes_ = idTexels.size() * 4;
  objects_ = upload(device, objects, "decoupled objects");
  shadelInstances_ = upload(device, tables.instances, "shadel instances");
  levelRects_ = upload(device, tables.levelRects, "level rects");
  ownedEntries_ = upload(device, tables.ownedEntries, "owned remap entries");
  idMaps_ = upload(device, idTexels, "triangle-ID maps");
  const uint64_t entriesPerSide = uint64_t(1) << (settings_.sheetSizeLog2 - 6);
  remapBytes_ = entriesPerSide * entriesPerSide * sizeof(shadel::RemapEntry);
  readback_ = gpu::Buffer(device.context(), device.memory(),
                          {sizeof(ShadeCounters), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryLocation::Readback,
                           "shade counters readback", "readback"});
  std::memset(readback_.mapped(), 0, sizeof(ShadeCounters));
  params_ = gpu::Buffer(device.context(), device.memory(),
                        {sizeof(DecoupledParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryLocation::Upload,
                         "decoupled params", "decoupled tables"});
  initialized_ = true;
}

// Objects in mode auto that are tiny on screen this frame go forward; they
// keep their shadel space and simply mark nothing. Objects outside the view
// are not shaded at all (nor their materials compiled).
void DecoupledShading::selectFrameObjects(const render::FrameInputs& in) {
  frameDraws_.clear();
  frameObjects_.clear();
  frameMaterials_.clear();
  frameForwardDraws_.clear();
  for (const uint32_t d : forwardDraws_)
    if (sphereInFrustum(in.viewProjection, drawSpheres_[d])) frameForwardDraws_.push_back(d);
  for (uint32_t object = 0; object < uint32_t(decoupledDraws_.size()); ++object) {
    const glm::vec4 sphere = drawSpheres_[decoupledDraws_[object]];
    if (!sphereInFrustum(in.viewProjection, sphere)) continue;
    const float distance = glm::distance(glm::vec3(sphere), in.cameraPosition);
    const bool tiny = objectAutomatic_[object] && in.pixelsPerUnitAtUnitDistance > 0.0f && distance > sphere.w &&
                      sphere.w * in.pixelsPerUnitAtUnitDistance / distance < kTinyObjectPixels;
    if (tiny) {
      frameForwardDraws_.push_back(decoupledDraws_[object]);
    } else {
      frameDraws_.push_back(decoupledDraws_[object]);
      frameObjects_.push_back(object);
      frameMaterials_.push_back(objectMaterials_[object]);
    }
  }
}

graph::ResourceHandle DecoupledShading::declare(graph::RenderGraph& graph, const render::FrameInputs& in) {
  if (!initialized_) initialize(in);
  // The adjuster reads the counters of the frame before (complete: frames are
  // waited for), which was rendered with lastFrameBias_.
  if (frames_ > 0 && !settings_.fixedBias) {
    const auto c = stats().counters;
    bias_ = adjuster_.update({lastFrameBias_, uint64_t(c.chunksMarked), storage_.capacityChunks(), c.overflowChunks});
  }
  lastFrameBias_ = bias_;
  ++frames_;

  const auto objectCount = uint32_t(decoupledDraws_.size());

  selectFrameObjects(in);
  layerPlan_ = planLayers(in.view.materials, frameObjects_, frameMaterials_);

  // An entry takes up to 64 chunks from one partition at once: keep partitions
  // at least 4 entries large, so a small storage does not fail every big entry.
  // The chunk ring support-expand adds around visible regions comes on top
  // (measured: +70% on the courtyard at 192², less at larger outputs).
  const double supportScale = layerPlan_.needsSupport ? kSupportStorageScale : 1.0;
  const uint32_t chunks = settings_.storageChunks
                              ? settings_.storageChunks
                              : shadel::chunksForOutput(in.width, in.height, settings_.storageFactor * supportScale);
  storage_ = shadel::storageLayoutFor(chunks, std::clamp<uint32_t>(chunks / 256, 1, kStorageCounters));
  const DecoupledParams params{bias_, settings_.sheetSizeLog2 - 6, storage_.widthChunks, storage_.chunksPerCounter,
                               ownedEntryCount_, objectCount, storage_.capacityChunks(),
                               storage_.counterCount, {}};
  params_.write(&params, sizeof params);
  render::SceneView forwardView{in.view.scene, in.view.frameUniforms, frameForwardDraws_, in.view.materials,
                                in.view.layerTextures};
  render::DecoupledFrame frame{.view = {in.view.scene, in.view.frameUniforms, frameDraws_, in.view.materials,
                                                        in.view.layerTextures},
                               .objectIds = frameObjects_,
                               .objectDraws = decoupledDraws_,
                               .params = params_, .objects = objects_, .shadelInstances = shadelInstances_,
                               .levelRects = levelRects_, .ownedEntries = ownedEntries_, .idMaps = idMaps_,
                               .ownedEntryCount = ownedEntryCount_, .objectCount = objectCount,
                               .filter = settings_.filter,
                               .levelView = settings_.view == DebugView::Level};
  const auto history = history_.declare(graph, in.device, in.executor, in.view.materials, layerPlan_.persistent,
                                        storage_.widthTexels(), storage_.heightTexels(), remapBytes_, frames_);
  frame.remap = history.remap;
  frame.counters = graph.createBuffer("shade counters", {.size = sizeof(ShadeCounters)});
  frame.work = graph.createBuffer("work", {.size = workBufferBytes(objectCount, storage_.capacityChunks())});
  frame.args = graph.createBuffer("dispatch args", {.size = std::max<uint64_t>(12ull * objectCount, 12)});
  frame.shadedColor = graph.createImage(
      "shade storage", {.format = graph::Format::RGBA16F,
                        .size = graph::Size::absolute(storage_.widthTexels(), storage_.heightTexels())});
  auto readback = graph.importBuffer("shade counters readback", {.size = sizeof(ShadeCounters)}, {},
                                     {graph::Layout::Undefined, graph::PipelineStage::AllCommands, graph::AccessFlag::None});
  in.executor.bindBuffer(readback, readback_);

  passes::ForwardTargets targets;
  targets.depth = graph.createImage("depth", {.format = graph::Format::D32F});
  targets.color = graph.createImage("hdr", {.format = graph::Format::RGBA16F});
  targets.depth = passes::addZPrepass(graph, in.view, targets.depth);
  // With objects allocated but none shaded this frame, the counters are
  // still cleared and read back (the adjuster and stats see a zero frame).
  const bool shading = !frameObjects_.empty();
  if (objectCount) passes::addShadelClear(graph, frame);
  if (shading) {
    passes::addShadelMark(graph, frame, targets.depth);
    if (layerPlan_.needsSupport) passes::addSupportExpand(graph, frame);
    passes::addShadelAllocate(graph, frame);
    passes::addWorkAggregate(graph, frame);
    addLayerPasses(graph, frame, in.view.materials, history);
  }
  targets = passes::addForwardOpaque(graph, forwardView, targets);
  if (passes::hasAlphaMode(forwardView, scene::AlphaMode::Mask)) targets = passes::addAlphaMask(graph, forwardView, targets);
  if (shading) targets.color = passes::addComposite(graph, frame, targets.color, targets.depth);
  if (objectCount) {
    auto& copy = graph.addPass("counters-readback", graph::QueueClass::Graphics, graph::PassKind::Transfer);
    copy.read(frame.counters, graph::Access::TransferSrc);
    readback = copy.write(readback, graph::Access::TransferDst);
    copy.execute([counters = frame.counters, readback](PassContext& ctx) {
      const VkBufferCopy region{0, 0, sizeof(ShadeCounters)};
      vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(counters).handle(), ctx.buffer(readback).handle(), 1, &region);
    });
  }
  if (passes::hasAlphaMode(forwardView, scene::AlphaMode::Blend))
    targets.color = passes::addAlphaBlend(graph, forwardView, in.cameraPosition, targets);
  if (shading && settings_.view == DebugView::Occupancy)
    targets.color = passes::addOccupancyView(graph, frame, sheetRegionOrigin_, sheetRegionSize_);
  if (shading && settings_.view == DebugView::Sheet) targets.color = passes::addSheetView(graph, frame);
  const bool passthrough = settings_.view != DebugView::Final;  // debug colours as they are
  // Plugins' passes on the HDR colour, in the order they were registered.
  for (const auto& post : in.view.materials.postPasses()) targets.color = post.declare(graph, targets.color);
  const auto exposure = passes::addExposure(graph, targets.color);
  return passes::addTonemap(graph, targets.color, exposure, in.output, passthrough);
}

void DecoupledShading::addLayerPasses(graph::RenderGraph& graph, render::DecoupledFrame& frame,
                                      const plugin::Registry& materials, const LayerHistory::Declared& history) {
  // The current version of each intermediate layer's own image.
  std::map<std::string, graph::ResourceHandle> images;
  for (const auto& name : layerPlan_.images) {
    const auto& layer = materials.layer(name);
    images[name] = layer.persistent
                       ? history.layers.at(name).current
                       : graph.createImage("layer " + name,
                                           {.format = layer.format, .size = graph::Size::absolute(
                                                                        storage_.widthTexels(), storage_.heightTexels())});
  }
  for (size_t depth = 0; depth < layerPlan_.depths.size(); ++depth) {
    std::vector<passes::LayerShadeStep> steps;
    for (const auto& planned : layerPlan_.depths[depth]) {
      const auto& layer = materials.layer(planned.layer);
      passes::LayerShadeStep step{&layer, planned.objects, planned.final ? frame.shadedColor : images.at(layer.name)};
      for (const auto& read : layer.reads) step.inputs.push_back(images.at(read.layer));
      if (layer.persistent) {
        step.history = history.layers.at(layer.name).history;
        const auto& persistent = layerPlan_.persistent;
        step.persistentSlot = uint32_t(std::find(persistent.begin(), persistent.end(), layer.name) - persistent.begin());
      }
      steps.push_back(std::move(step));
    }
    const std::string name = depth == 0 ? "layer-shade" : "layer-shade #" + std::to_string(depth + 1);
    passes::addLayerShade(graph, frame, name, steps, {history.previousRemap, history.valid});
    for (size_t i = 0; i < steps.size(); ++i)
      (layerPlan_.depths[depth][i].final ? frame.shadedColor : images[steps[i].layer->name]) = steps[i].output;
  }
}

DecoupledStats DecoupledShading::stats() const {
  DecoupledStats s;
  if (readback_) std::memcpy(&s.counters, readback_.mapped(), sizeof s.counters);
  s.bias = lastFrameBias_;
  s.objects = uint32_t(frameObjects_.size());
  s.capacityChunks = storage_.capacityChunks();
  s.storageBytes = uint64_t(storage_.widthTexels()) * storage_.heightTexels() * 8;
  s.remapBytes = remapBytes_;
  s.historyBytes = history_.bytes();
  s.layerDispatches = layerPlan_.dispatches;
  for (const auto& steps : layerPlan_.depths)
    for (const auto& step : steps) s.layers.push_back(step.layer);
  for (uint32_t slot = 0; slot < layerPlan_.persistent.size(); ++slot)
    s.layerReuse.push_back({layerPlan_.persistent[slot], s.counters.layerReused[slot], s.counters.layerComputed[slot]});
  s.idMapBytes = idMapBytes_;
  return s;
}

}  // namespace sg::plugins
