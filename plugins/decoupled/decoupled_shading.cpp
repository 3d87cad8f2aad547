#include "decoupled_shading.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>

#include <shadelgraph/gpu/pass_context.hpp>
#include <decoupled_frame.hpp>
#include <shadelgraph/render/frustum.hpp>
#include <shadelgraph/render/material_variants.hpp>
#include <shadelgraph/scene/scene.hpp>
#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/id_map_cache.hpp>
#include <shadelgraph/shadel/level0_resolution.hpp>
#include <shadelgraph/shadel/level_selection.hpp>
#include <shadelgraph/shadel/shadel_gpu_tables.hpp>

#include "layer-shade/layer_shade.hpp"
#include "live-entry-blocks/live_entry_blocks.hpp"
#include "shade-frame/shade_frame_work.hpp"
#include "shadel-mark/shadel_mark.hpp"
#include "id_map_budget.hpp"
#include "layer_rate.hpp"
#include "shade-reuse/shade_reuse.hpp"

namespace sg::plugins {
namespace {

// Where the chunk slots rest between frames: any shader use.
const graph::ResourceState kResting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                    graph::AccessFlag::ShaderStorageRead | graph::AccessFlag::ShaderStorageWrite};

template <class T>
gpu::Buffer upload(gpu::Device& device, const std::vector<T>& data, const char* name, VkBufferUsageFlags usage = 0) {
  const size_t bytes = std::max<size_t>(data.size() * sizeof(T), 16);
  gpu::Buffer buffer(device.context(), device.memory(),
                     {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | usage, gpu::MemoryLocation::Upload, name,
                      "decoupled tables"});
  if (!data.empty()) buffer.write(data.data(), data.size() * sizeof(T));
  return buffer;
}

// How an object's level follows its footprint (DecoupledFrame::levelRules).
uint32_t levelRule(const scene::Scene& scene, uint32_t material, const PrimitiveChoice& primitive) {
  if (scene::samplesUnmipmappedTexture(scene, int(material))) return shadel::packLevelRule(shadel::kUnmipmappedLevelRule);
  if (primitive.automaticChart && scene::samplesTexture(scene, int(material)))
    return shadel::packLevelRule(shadel::kResampledTextureLevelRule);
  return shadel::packLevelRule({});
}

// A material that reads neighbours (support) or its own last value
// (persistent layers) cannot have some chunks reused and others shaded.
// (View-independent layers can: shade-reuse copies their images too.)
bool reshadedWhole(const plugin::Registry& registry, const plugin::MaterialStack& material) {
  if (supportRadius(registry, material) > 0) return true;
  for (const auto& layer : material.layers)
    if (registry.layer(layer).persistent) return true;
  return false;
}

}  // namespace

DecoupledShading::DecoupledShading(std::vector<ShadingChoice> choices, DecoupledSettings settings)
    : choices_(std::move(choices)), settings_(settings), adjuster_(settings.adjuster) {
  bias_ = settings_.fixedBias.value_or(adjuster_.bias());
  if (settings_.shadeBudgetMs) budget_.emplace(*settings_.shadeBudgetMs, settings_.budgetMsPerChunk);
}

DecoupledShading::~DecoupledShading() = default;

void DecoupledShading::observeTimings(const gpu::FrameTimings& timings) {
  if (!budget_ || !countersPending_) return;
  double ms = 0.0;
  for (const auto& pass : timings.passes)
    if (pass.name.starts_with("layer-shade")) ms += pass.gpuMs;
  budget_->observeCost(ms, stats().counters.chunksShaded);
}

void DecoupledShading::createTables(gpu::Device& device) {
  space_ = std::make_unique<shadel::ShadelSpace>(shadel::ShadelSpaceConfig{settings_.sheetSizeLog2});
  const uint64_t entriesPerSide = uint64_t(1) << (settings_.sheetSizeLog2 - 6);
  remapBytes_ = entriesPerSide * entriesPerSide * sizeof(shadel::RemapEntry);
  readback_ = gpu::Buffer(device.context(), device.memory(),
                          {sizeof(ShadeCounters), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryLocation::Readback,
                           "shade counters readback", "readback"});
  std::memset(readback_.mapped(), 0, sizeof(ShadeCounters));
  for (auto& params : params_)
    params = gpu::Buffer(device.context(), device.memory(),
                         {sizeof(DecoupledParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryLocation::Upload,
                          "decoupled params", "decoupled tables"});
}

void DecoupledShading::syncObjects(const render::FrameContext& ctx) {
  const auto& in = ctx.inputs();
  const auto& draws = ctx.gpuScene().draws();
  const plugin::Registry& materials = ctx.registry();
  if (slots_.empty()) {
    slots_.resize(draws.size());
    identity_.resize(draws.size());
    for (uint32_t d = 0; d < draws.size(); ++d) identity_[d] = d;
  }
  shadel::IdMapCache cache;
  std::vector<uint32_t> toAllocate;  // draws that now ask for decoupled
  for (uint32_t d = 0; d < draws.size(); ++d) {
    const auto& draw = draws[d];
    const ShadingChoice& choice = choices_[draw.instance];
    const PrimitiveChoice& primitive = choice.primitives[draw.primitive];
    ObjectSlot& slot = slots_[d];
    slot.instance = draw.instance;
    slot.primitive = draw.primitive;
    const plugin::MaterialStack& material = materials.material(draw.materialStack);
    const bool wanted = in.objectModes[draw.instance] != scene::ShadingMode::Forward;
    slot.reason = !wanted                ? "forward by request"
                  : !choice.eligible     ? choice.reason
                  : !primitive.eligible  ? primitive.reason  // alpha-blended
                  : !materials.runsIn(material, plugin::ShadingPath::Decoupled)
                      ? "material '" + material.name + "' has forward-only layers"
                      : "";
    const bool want = slot.reason.empty();
    if (want && slot.allocated &&
        (slot.record.world != draw.world || slot.record.material != draw.material ||
         slot.materialStack != draw.materialStack)) {
      // Moved or given another material: what it stored no longer holds. The
      // record reaches the GPU with this frame's reuse flags (chooseReuse).
      if (slot.record.material != draw.material || slot.materialStack != draw.materialStack) slot.materialFrame = frames_;
      slot.record.world = draw.world;
      slot.record.material = draw.material;
      slot.record.supportChunks = supportRadius(materials, material) > 0 ? 1u : 0u;
      slot.levelRule = levelRule(in.scene, draw.material, primitive);
      slot.unmipmapped = shadel::unmipmappedTexels(in.scene, primitiveMesh(in.scene.meshes[size_t(in.scene.instances[draw.instance].mesh)], draw.primitive));
      slot.materialStack = draw.materialStack;
      slot.changedFrame = frames_;
      slot.reshadedWhole = reshadedWhole(materials, material);
    }
    if (want == slot.allocated) continue;
    tablesDirty_ = true;
    if (!want) {
      space_->release(d);
      slot.allocated = false;
      --allocatedObjects_;
      continue;
    }
    toAllocate.push_back(d);
  }

  // Each primitive is an object of its own: its own triangle-ID map (triangle
  // IDs count from its first index) and shadel space. The maps not baked yet
  // are sized together, so that all fit the one buffer (id_map_budget.hpp).
  // Layer shading reads the maps as R32UI texels (a uniform texel buffer).
  const auto& limits = in.device.context().properties().limits;
  const uint64_t limit = std::min<uint64_t>(limits.maxStorageBufferRange, uint64_t(limits.maxTexelBufferElements) * 4);
  struct NewMap {
    scene::Mesh mesh;
    scene::ChartVerdict chart;
    uint32_t level0 = 0;
    uint32_t instance = 0;  // the first object asking for it
  };
  std::map<std::pair<int, uint32_t>, NewMap> newMaps;
  for (const uint32_t d : toAllocate) {
    const std::pair<int, uint32_t> key{in.scene.instances[draws[d].instance].mesh, draws[d].primitive};
    if (idMaps_.contains(key) || noIdMapRoom_.contains(key)) continue;
    auto it = newMaps.find(key);
    if (it == newMaps.end()) {
      NewMap map{primitiveMesh(in.scene.meshes[size_t(key.first)], key.second), {}, 0, draws[d].instance};
      map.chart = scene::chooseShadingChart(map.mesh);
      map.level0 = shadel::chooseLevel0Size(map.mesh, map.chart, shadel::meshTextureDensity(in.scene, map.mesh));
      it = newMaps.emplace(key, std::move(map)).first;
    }
    // Narrow triangles at least at the screen's rate in the view that first
    // shows them (every instance of the mesh): a level 0 capped below it
    // magnifies their shading away (thin bevels vanish; OrientationTest 27 dB).
    if (!settings_.screenRateLevel0) continue;
    const uint32_t screen = shadel::screenRateLevel0Size(it->second.mesh, it->second.chart, draws[d].world,
                                                         in.viewProjection, in.width, in.height, it->second.level0);
    it->second.level0 = std::max(it->second.level0, std::min(screen, shadel::Level0Options{}.maxSize));
  }
  if (!newMaps.empty()) {
    std::vector<uint32_t> sizes;
    for (const auto& [key, map] : newMaps) sizes.push_back(map.level0);
    const uint64_t budget = limit / sizeof(uint32_t) - std::min<uint64_t>(idTexels_.size(), limit / sizeof(uint32_t));
    sizes = fitIdMapSizes(std::move(sizes), budget, shadel::IdMapOptions{}.minLevelSize, shadel::Level0Options{}.minSize);
    size_t i = 0;
    for (auto& [key, map] : newMaps) {
      if (sizes[i] < map.level0) shrunkIdMaps_.push_back({map.instance, key.second, map.level0, sizes[i], limit});
      map.level0 = sizes[i++];
    }
  }

  for (const uint32_t d : toAllocate) {
    const auto& draw = draws[d];
    const PrimitiveChoice& primitive = choices_[draw.instance].primitives[draw.primitive];
    ObjectSlot& slot = slots_[d];
    const plugin::MaterialStack& material = materials.material(draw.materialStack);
    const std::pair<int, uint32_t> key{in.scene.instances[draw.instance].mesh, draw.primitive};
    auto it = idMaps_.find(key);
    if (it == idMaps_.end()) {
      if (noIdMapRoom_.contains(key)) {
        slot.reason = "no room for its triangle-ID map";
        continue;
      }
      const NewMap& planned = newMaps.at(key);
      auto map = cache.loadOrBake(planned.mesh, planned.chart, {.level0Size = planned.level0});
      // Still too big (every map at the smallest level 0): the object stays forward.
      if ((idTexels_.size() + map.texels.size()) * sizeof(uint32_t) > limit) {
        noIdMapRoom_.insert(key);
        slot.reason = "no room for its triangle-ID map";
        continue;
      }
      const auto offset = uint32_t(idTexels_.size());
      idTexels_.insert(idTexels_.end(), map.texels.begin(), map.texels.end());
      it = idMaps_.emplace(key, std::pair{map.levels, offset}).first;
    }
    const auto& [levels, offset] = it->second;
    const auto result = space_->allocate(d, levels);
    if (!result.ok()) {
      slot.reason = "no shadel space: " + result.message;
      continue;
    }
    slot.allocated = true;
    slot.materialStack = draw.materialStack;
    slot.changedFrame = frames_;
    slot.materialFrame = frames_;
    slot.reshadedWhole = reshadedWhole(materials, material);
    ++allocatedObjects_;
    slot.record = {draw.world, draw.firstIndex, draw.vertexOffset, draw.indexCount / 3, draw.material, offset,
                   uint32_t(primitive.uvSet), primitive.tileOffset, supportRadius(materials, material) > 0 ? 1u : 0u, 0u, 0u, 0u};
    slot.levelRule = levelRule(in.scene, draw.material, primitive);
    slot.unmipmapped = shadel::unmipmappedTexels(in.scene, primitiveMesh(in.scene.meshes[size_t(key.first)], key.second));
  }
}

std::vector<DecoupledShading::RunTimeForward> DecoupledShading::runTimeForward() const {
  std::vector<RunTimeForward> forward;
  for (const auto& slot : slots_) {
    const ShadingChoice& choice = choices_[slot.instance];
    // Objects and primitives the choices refused say why at load already.
    if (slot.allocated || !choice.decoupled || !choice.primitives[slot.primitive].eligible) continue;
    if (!slot.reason.empty()) forward.push_back({slot.instance, slot.primitive, slot.reason});
  }
  return forward;
}

void DecoupledShading::uploadTables(gpu::Device& device) {
  tablesDirty_ = false;
  visibilityFrame_ = 0;  // the next live-entry-blocks visits every live object once
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
  std::vector<DecoupledObject> objects;
  for (const auto& slot : slots_) objects.push_back(slot.record);
  ownedEntryCount_ = uint32_t(tables.ownedEntries.size());
  ownedRuns_ = shadel::ownedEntryRuns(tables);
  idMapBytes_ = idTexels_.size() * 4;
  // Earlier frames have completed (the executor waits for each), so the old tables are free.
  for (auto& buffer : objects_) buffer = upload(device, objects, "decoupled objects");
  shadelInstances_ = upload(device, tables.instances, "shadel instances");
  levelRects_ = upload(device, tables.levelRects, "level rects", VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  ownedEntries_ = upload(device, tables.ownedEntries, "owned remap entries");
  chunkSlots_.setOwnedEntries(tables.ownedEntries);  // the chunk slots follow the owned entries
  idMapTexels_ = {};  // before the buffer it views
  idMapBuffer_ = upload(device, idTexels_, "triangle-ID maps", VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  idMapTexels_ = gpu::BufferView(device.context(), idMapBuffer_.handle(), idMapBuffer_.size(), VK_FORMAT_R32_UINT, 4,
                                 "triangle-ID maps (R32UI texels)");
}

// Objects in mode auto go forward in frames where decoupled shading cannot
// serve them: tiny on screen, or sampling a texture without mip levels that
// is minified (unmipmapped_minification.hpp). They keep their shadel space
// and simply mark nothing. Objects outside the view are not in the frame's
// draws at all (nor their materials compiled).
void DecoupledShading::selectFrameObjects(render::FrameContext& ctx) {
  frameObjects_.clear();
  frameMaterials_.clear();
  frameForward_.clear();
  const auto& in = ctx.inputs();
  const auto& draws = ctx.gpuScene().draws();
  std::vector<uint32_t> forward;
  for (const uint32_t d : ctx.draws().forward) {
    const glm::vec4 sphere = in.drawSpheres[d];
    const float distance = glm::distance(glm::vec3(sphere), in.cameraPosition);
    const bool automatic = in.objectModes[draws[d].instance] == scene::ShadingMode::Auto;
    std::string why;
    if (automatic && slots_[d].allocated && in.pixelsPerUnitAtUnitDistance > 0.0f) {
      const bool tiny = distance > sphere.w && sphere.w * in.pixelsPerUnitAtUnitDistance / distance < kTinyObjectPixels;
      // The sphere's centre stands for the object's distance; the uniform part of its world scale for its size.
      const double scale = std::cbrt(std::abs(double(glm::determinant(glm::mat3(draws[d].world)))));
      const double texelsPerPixel = shadel::unmipmappedTexelsPerPixel(slots_[d].unmipmapped, scale, distance,
                                                                      in.pixelsPerUnitAtUnitDistance);
      if (tiny) {
        why = "tiny on screen";
      } else if (settings_.forwardMinifiedUnmipmapped && texelsPerPixel > shadel::kMaxUnmipmappedTexelsPerPixel) {
        char text[160];
        std::snprintf(text, sizeof text, "texture '%s' has no mip levels and is minified, %.1f texels per pixel",
                      slots_[d].unmipmapped.texture.c_str(), texelsPerPixel);
        why = text;
      }
    }
    if (!why.empty()) frameForward_.push_back({draws[d].instance, draws[d].primitive, why});
    if (!slots_[d].allocated || !why.empty()) {
      forward.push_back(d);
    } else {
      frameObjects_.push_back(d);
      frameMaterials_.push_back(draws[d].materialStack);
    }
  }
  ctx.draws().forward = std::move(forward);
  ctx.draws().decoupled = frameObjects_;
}

void DecoupledShading::markShadowChanges(const render::FrameContext& ctx) {
  const auto& in = ctx.inputs();
  const auto& draws = ctx.gpuScene().draws();
  const auto& lights = in.scene.lights;
  std::vector<bool> shadowed(lights.size(), false);
  for (const render::ShadowView& v : in.shadowViews) shadowed[v.light] = true;
  const bool first = lastWorlds_.size() != draws.size() || lastShadowed_.size() != lights.size();
  // Per moved caster and light: where its shadow was and is (spheres).
  struct MovedCaster {
    uint32_t light;
    glm::vec4 was, is;
  };
  std::vector<MovedCaster> moved;
  std::vector<bool> lightChanged(lights.size(), false);
  if (!first) {
    for (uint32_t l = 0; l < lights.size(); ++l) lightChanged[l] = shadowed[l] != lastShadowed_[l];
    for (uint32_t d = 0; d < draws.size(); ++d) {
      if (draws[d].world == lastWorlds_[d]) continue;
      for (uint32_t l = 0; l < lights.size(); ++l)
        if (shadowed[l] && (render::lightReaches(lights[l], in.drawSpheres[d]) || render::lightReaches(lights[l], lastSpheres_[d])))
          moved.push_back({l, lastSpheres_[d], in.drawSpheres[d]});
    }
  }
  for (uint32_t d = 0; d < slots_.size(); ++d) {
    ObjectSlot& slot = slots_[d];
    if (!slot.allocated || slot.changedFrame == frames_) continue;
    const glm::vec4& receiver = in.drawSpheres[d];
    bool changed = false;
    for (uint32_t l = 0; l < lights.size() && !changed; ++l)
      changed = lightChanged[l] && render::lightReaches(lights[l], receiver);
    for (const MovedCaster& m : moved) {
      if (changed) break;
      changed = render::shadowMayFallOn(lights[m.light], m.was, receiver) ||
                render::shadowMayFallOn(lights[m.light], m.is, receiver);
    }
    if (changed) slot.changedFrame = frames_;
  }
  lastWorlds_.clear();
  for (const auto& draw : draws) lastWorlds_.push_back(draw.world);
  lastSpheres_.assign(in.drawSpheres.begin(), in.drawSpheres.end());
  lastShadowed_ = std::move(shadowed);
}

void DecoupledShading::chooseReuse(bool historyValid, const plugin::Registry& materials) {
  reuseAny_ = false;
  for (auto& slot : slots_) {
    if (!slot.allocated) continue;
    // Overlapping, the raster frame always reuses: its shade frame runs after it.
    slot.record.reuse = (!shadeFrame_ || overlapping()) && historyValid && slot.changedFrame != frames_ && !slot.reshadedWhole ? 1u : 0u;
    reuseAny_ = reuseAny_ || slot.record.reuse;
    const LayerKeepState keep{.historyValid = historyValid && settings_.keepViewIndependentLayers,
                              .materialChanged = slot.materialFrame == frames_,
                              .moved = slot.changedFrame == frames_,
                              // Budget mode has no shade frames: kept layers refresh every 8th raster frame.
                              .shadeFrame = shadeFrame_ || budget_.has_value(),
                              .shadeFrameIndex = budget_ ? frames_ : shadeFrames_};
    slot.record.keepLayers =
        keptLayerBits(materials, materials.material(slot.materialStack), layerPlan_.persistent, keep);
  }
  // Every record, rewritten each frame (reuse flags, transforms, materials):
  // the last frame that read the buffer has completed (the executor waits for each).
  std::vector<DecoupledObject> objects;
  for (const auto& slot : slots_) objects.push_back(slot.record);
  if (!objects.empty()) objects_[ring()].write(objects.data(), objects.size() * sizeof(DecoupledObject));
}

void DecoupledShading::prepare(render::FrameContext& ctx) {
  const auto& in = ctx.inputs();
  if (preparedFrame_ == in.frameNumber) return;
  preparedFrame_ = in.frameNumber;
  // The counters of the frame before (complete: frames are waited for) join the totals.
  if (countersPending_) {
    const auto c = stats().counters;
    if (!shadeFrame_) chunksFilled_ += c.chunksShaded - c.chunksRefreshed;
    chunksReused_ += c.chunksReused;
    countersPending_ = false;
    if (budget_) {
      const uint64_t filled = c.chunksShaded - c.chunksRefreshed;
      staleAge_ = budget_->nextAgeLimit(filled, shadeFrame_ ? 0 : filled, c.staleAgeChunks, staleAge_);
    }
  }
  ++frames_;
  const uint32_t rate = std::max(settings_.shadeRate, 1u);
  // Budget mode has no shade frames but the first (nothing is stored yet).
  shadeFrame_ = budget_ ? frames_ == 1 : (frames_ - 1) % rate == 0;
  if (budget_ && frames_ == 1) staleAge_ = {};
  shadeFrames_ += shadeFrame_ ? 1 : 0;
  if (!space_) createTables(in.device);
  syncObjects(ctx);
  markShadowChanges(ctx);
  if (tablesDirty_) {
    in.executor.finish();  // a frame still in flight may read the tables
    uploadTables(in.device);
  }
  // The adjuster reads the counters of the frame before, which was rendered
  // with lastFrameBias_.
  if (frames_ > 1 && !settings_.fixedBias) {
    const auto c = stats().counters;
    bias_ = adjuster_.update({lastFrameBias_, uint64_t(c.chunksMarked), storage_.capacityChunks(), c.overflowChunks});
  }
  lastFrameBias_ = bias_;

  const auto objectCount = uint32_t(slots_.size());
  selectFrameObjects(ctx);
  // Only the entries of objects shaded now or holding stored chunks: culled
  // objects cost the per-entry passes nothing. The debug views of the sheet
  // show every entry, so they get them all.
  const std::vector<uint32_t> live = liveInstances_.next(frameObjects_);
  std::vector<shadel::EntrySpan>& spans = liveSpans_[ring()];
  const bool everyEntry = !settings_.liveEntrySpans || settings_.view == DebugView::Occupancy ||
                          settings_.view == DebugView::Sheet;
  blocksWanted_ = settings_.skipOccludedEntries && !everyEntry;
  if (everyEntry)
    spans.assign(ownedEntryCount_ ? 1 : 0, shadel::EntrySpan{0, ownedEntryCount_});
  else
    spans = shadel::liveEntrySpans(ownedRuns_, live);
  const plugin::Registry& materials = ctx.registry();
  layerPlan_ = planLayers(materials, frameObjects_, frameMaterials_);

  // The storage's partitions only round its capacity now (shadel-allocate
  // takes chunks from one free list). The chunk ring support-expand adds around visible regions comes on top
  // (measured: +70% on the courtyard at 192², less at larger outputs).
  const double supportScale = layerPlan_.needsSupport ? kSupportStorageScale : 1.0;
  const uint32_t chunks = settings_.storageChunks
                              ? settings_.storageChunks
                              : shadel::chunksForOutput(in.width, in.height, settings_.storageFactor * supportScale);
  storage_ = shadel::storageLayoutFor(chunks, std::clamp<uint32_t>(chunks / 256, 1, kStorageCounters));
  const bool keepShading = rate > 1 || budget_.has_value();
  // Stable allocation: the chunk slots and free list, kept while the owned
  // entries and the storage capacity stay the same.
  if (hasObjects()) chunkSlots_.prepare(in.device, in.executor, storage_.capacityChunks());
  const DecoupledParams params{bias_,          settings_.sheetSizeLog2 - 6, storage_.widthChunks,
                               ownedEntryCount_, objectCount,   storage_.capacityChunks(),
                               uint32_t(frames_), budget_ ? staleAge_.limit : 0u,
                               keepShading ? 1u : 0u, staleAge_.fraction};
  params_[ring()].write(&params, sizeof params);
  graph::RenderGraph& graph = ctx.graph();
  frame_.reset();
  if (!hasObjects()) return;
  levelRules_.clear();
  for (const auto& slot : slots_) levelRules_.push_back(slot.levelRule);
  frame_.emplace(passes::DecoupledFrame{.view = ctx.view(frameObjects_),
                                        .objectIds = frameObjects_,
                                        .objectDraws = identity_,
                                        .levelRules = levelRules_,
                                        .params = params_[ring()], .objects = objects_[ring()], .shadelInstances = shadelInstances_,
                                        .levelRects = levelRects_, .ownedEntries = ownedEntries_, .idMaps = idMapTexels_.handle(),
                                        .ownedEntryCount = ownedEntryCount_, .objectCount = objectCount,
                                        .liveSpans = liveSpans_[ring()],
                                        .filter = settings_.filter,
                                        .baseline = settings_.baseline,
                                        .levelView = settings_.view == DebugView::Level,
                                        .layerShadeInvocations = settings_.layerShadeInvocations,
                                        // Whole chunks where stored shadels may be served in a later frame,
                                        // and in the sheet view (it shows every stored texel).
                                        .shadelMasks = settings_.shadelMasks && !keepShading &&
                                                       layerPlan_.persistent.empty() && !settings_.baseline &&
                                                       settings_.view != DebugView::Sheet});
  passes::DecoupledFrame& frame = *frame_;
  // Where the decoupled draws can land on screen: shadel-mark-requests merges there only.
  glm::ivec4 cover(int(in.width), int(in.height), 0, 0);
  for (const uint32_t d : frame.view.draws) {
    const glm::ivec4 r = render::boxScreenRect(in.viewProjection, in.drawBounds[d], in.width, in.height);
    if (r.z <= r.x || r.w <= r.y) continue;
    cover = glm::ivec4(glm::min(glm::ivec2(cover), glm::ivec2(r)), glm::max(glm::ivec2(cover.z, cover.w), glm::ivec2(r.z, r.w)));
  }
  std::copy_n(&cover.x, 4, frame.cover);
  offerDepthPassDraws(ctx);
  declaredHistory_ = history_.declare(graph, in.device, in.executor, materials, layerPlan_.persistent, keepShading,
                                      storage_.widthTexels(), storage_.heightTexels(), remapBytes_, frames_,
                                      std::to_string(in.width) + "x" + std::to_string(in.height));
  chooseReuse(declaredHistory_.valid, materials);
  countersPending_ = true;  // counters-readback runs whenever objects are allocated
  frame.remap = declaredHistory_.remap;
  frame.slots = graph.importPersistentBuffer("chunk slots", {.size = chunkSlots_.bytes()}, kResting);
  in.executor.bindBuffer(frame.slots, chunkSlots_.buffer());
  frame.counters = graph.createBuffer("shade counters", {.size = sizeof(ShadeCounters)});
  frame.work = graph.createBuffer("work", {.size = workBufferBytes(objectCount, storage_.capacityChunks())});
  // One VkDispatchIndirectCommand per object, then shade-reuse's.
  frame.args = graph.createBuffer("dispatch args", {.size = 12ull * (objectCount + 1)});
  if (keepShading) {
    frame.shadedColor = declaredHistory_.shaded;
    frame.stamps = declaredHistory_.stamps;
  } else {
    frame.shadedColor = graph.createImage(
        "shade storage", {.format = graph::Format::RGBA16F,
                          .size = graph::Size::absolute(storage_.widthTexels(), storage_.heightTexels())});
  }
  readbackHandle_ = graph.importBuffer("shade counters readback", {.size = sizeof(ShadeCounters)}, {},
                                       {graph::Layout::Undefined, graph::PipelineStage::AllCommands, graph::AccessFlag::None});
  in.executor.bindBuffer(readbackHandle_, readback_);
}

namespace {
struct ShadelResource {
  const char* name;
  graph::ResourceHandle passes::DecoupledFrame::*handle;
};
constexpr ShadelResource kShadelResources[] = {{"shadel.remap", &passes::DecoupledFrame::remap},
                                               {"shadel.counters", &passes::DecoupledFrame::counters},
                                               {"shadel.work", &passes::DecoupledFrame::work},
                                               {"shadel.args", &passes::DecoupledFrame::args},
                                               {"shadel.shaded", &passes::DecoupledFrame::shadedColor}};
}  // namespace

void DecoupledShading::setFixedBias(std::optional<float> bias) {
  settings_.fixedBias = bias;
  bias_ = bias.value_or(adjuster_.bias());
}

void DecoupledShading::setFrameFilter(render::FrameContext& ctx, int filter) {
  if (!frame_) return;
  if (frame_->markedFilter >= 0) throw std::logic_error("the composite filter changed after shadel-mark was declared");
  frame_->filter = filter;
  offerDepthPassDraws(ctx);
}

void DecoupledShading::offerDepthPassDraws(render::FrameContext& ctx) {
  auto& offer = ctx.depthPassDraws();
  offer.reset();
  if (!frame_ || !shading() || !settings_.markRequests || !passes::markRequestsPossible(*frame_)) return;
  std::vector<uint32_t> draws(frame_->view.draws.begin(), frame_->view.draws.end());
  std::sort(draws.begin(), draws.end());
  offer = render::DepthPassDraws{.draws = std::move(draws),
                                 .draw = [frame = *frame_](PassContext& pc, VkBuffer indirect) {
                                   passes::drawMarkRequests(pc, frame, indirect);
                                 }};
}

void DecoupledShading::takeMarkRequests(render::FrameContext& ctx) {
  const auto& offer = ctx.depthPassDraws();
  frame_->markRequests = offer ? offer->target : graph::ResourceHandle{};
}

passes::DecoupledFrame& DecoupledShading::frame(render::FrameContext& ctx) {
  if (!frame_) throw plugin::FrameError("pass '" + ctx.passName() + "': decoupled shading was not prepared this frame");
  for (const auto& r : kShadelResources)
    if (ctx.has(r.name)) (*frame_).*r.handle = ctx.read(r.name);
  frame_->view.frameImages = ctx.resources();  // what layers' frameInputs sample
  return *frame_;
}

void DecoupledShading::publish(render::FrameContext& ctx, std::initializer_list<const char*> resources) {
  for (const char* name : resources)
    for (const auto& r : kShadelResources)
      if (std::string_view(r.name) == name) ctx.write(name, (*frame_).*r.handle);
}

void DecoupledShading::addCountersReadback(graph::RenderGraph& graph) {
  auto& copy = graph.addPass("counters-readback", graph::QueueClass::Graphics, graph::PassKind::Transfer);
  copy.read(frame_->counters, graph::Access::TransferSrc);
  readbackHandle_ = copy.write(readbackHandle_, graph::Access::TransferDst);
  copy.execute([counters = frame_->counters, readback = readbackHandle_](PassContext& ctx) {
    const VkBufferCopy region{0, 0, sizeof(ShadeCounters)};
    vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(counters).handle(), ctx.buffer(readback).handle(), 1, &region);
  });
}

void DecoupledShading::addShadeFrameTail(graph::RenderGraph& graph, const plugin::Registry& materials) {
  if (!frame_ || !overlapping() || !shadeFrame_) return;
  passes::DecoupledFrame& frame = *frame_;
  const passes::DecoupledFrame raster = frame;
  const bool reuse = reuseAny_;
  frame.work = graph.createBuffer("shade-frame work", {.size = workBufferBytes(frame.objectCount, storage_.capacityChunks())});
  frame.args = graph.createBuffer("shade-frame dispatch args", {.size = 12ull * (frame.objectCount + 1)});
  passes::addShadeFrameWork(graph, frame);
  reuseAny_ = false;
  addLayerPasses(graph, materials, "shade-frame ");
  reuseAny_ = reuse;
  frame.work = raster.work;
  frame.args = raster.args;
}

void DecoupledShading::addLayerPasses(graph::RenderGraph& graph, const plugin::Registry& materials,
                                      const std::string& prefix) {
  passes::DecoupledFrame& frame = *frame_;
  const LayerHistory::Declared& history = declaredHistory_;
  // The current version of each intermediate layer's own image.
  std::map<std::string, graph::ResourceHandle> images;
  for (const auto& name : layerPlan_.images) {
    const auto& layer = materials.layer(name);
    images[name] = layer.keepsValues()
                       ? history.layers.at(name).current
                       : graph.createImage("layer " + name,
                                           {.format = layer.format, .size = graph::Size::absolute(
                                                                        storage_.widthTexels(), storage_.heightTexels())});
  }
  // First the view-independent layers' values of the chunks that keep their
  // shading (they must be under every stored chunk; their images are pairs),
  // then the layers shade the rest. The shade storage keeps its chunks in place.
  if (reuseAny_) {
    std::vector<std::string> names;
    std::vector<passes::KeptLayerImage> kept;
    for (const auto& name : layerPlan_.persistent)
      if (materials.layer(name).viewIndependent() && images.contains(name)) {
        names.push_back(name);
        kept.push_back({history.layers.at(name).history, images.at(name), materials.layer(name).format});
      }
    if (!kept.empty()) passes::addShadeReuse(graph, frame, kept);
    for (size_t i = 0; i < kept.size(); ++i) images[names[i]] = kept[i].current;
  }
  for (size_t depth = 0; depth < layerPlan_.depths.size(); ++depth) {
    std::vector<passes::LayerShadeStep> steps;
    for (const auto& planned : layerPlan_.depths[depth]) {
      const auto& layer = materials.layer(planned.layer);
      passes::LayerShadeStep step{&layer, planned.objects, planned.final ? frame.shadedColor : images.at(layer.name)};
      for (const auto& read : layer.reads) step.inputs.push_back(images.at(read.layer));
      for (const auto& input : layer.frameInputs)
        step.frameInputs.push_back(render::frameInputImage(frame.view.frameImages, layer, input));
      if (layer.keepsValues()) {
        step.history = history.layers.at(layer.name).history;
        const auto& persistent = layerPlan_.persistent;
        step.persistentSlot = uint32_t(std::find(persistent.begin(), persistent.end(), layer.name) - persistent.begin());
      }
      steps.push_back(std::move(step));
    }
    const std::string name = prefix + (depth == 0 ? "layer-shade" : "layer-shade #" + std::to_string(depth + 1));
    passes::addLayerShade(graph, frame, name, steps, {history.valid});
    for (size_t i = 0; i < steps.size(); ++i)
      (layerPlan_.depths[depth][i].final ? frame.shadedColor : images[steps[i].layer->name]) = steps[i].output;
  }
}

void DecoupledShading::addLiveEntryBlocks(render::FrameContext& ctx) {
  passes::DecoupledFrame& frame = this->frame(ctx);
  if (!blocksWanted_ || passes::entryBlockCandidates(frame.liveSpans) == 0) return;
  const auto& in = ctx.inputs();
  const uint64_t bytes = 2ull * sizeof(uint32_t) * std::max<size_t>(slots_.size(), 1);
  if (!objectVisibility_ || objectVisibility_.size() != bytes) {
    objectVisibility_ = gpu::Buffer(in.device.context(), in.device.memory(),
                                    {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Device,
                                     "object visibility", "decoupled tables"});
    visibilityFrame_ = 0;
  }
  const auto visibility = ctx.graph().importPersistentBuffer("object visibility", {.size = bytes}, kResting);
  in.executor.bindBuffer(visibility, objectVisibility_);
  // Last frame's half is valid only if last frame wrote it: else every live object is visited once.
  const bool historyValid = visibilityFrame_ != 0 && visibilityFrame_ + 1 == frames_;
  passes::addLiveEntryBlocks(ctx.graph(), frame, {visibility, objectVisibility_.handle(), ring(), historyValid});
  visibilityFrame_ = frames_;
}

std::map<uint64_t, uint32_t> DecoupledShading::chunkAddresses(gpu::Device& device) const {
  return chunkSlots_.addresses(device);
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
  s.markedByRequests = frame_ && frame_->markRequests.valid();  // shadel-mark keeps them only where it merged them
  s.ownedEntries = ownedEntryCount_;
  s.liveEntries = uint32_t(shadel::entriesIn(liveSpans_[ring()]));
  s.visitedEntries = s.counters.entriesVisited;
  s.visitedEntryGroups = s.counters.entryGroupsVisited;
  s.liveSpans = uint32_t(liveSpans_[ring()].size());
  for (const auto& steps : layerPlan_.depths)
    for (const auto& step : steps) s.layers.push_back(step.layer);
  for (uint32_t slot = 0; slot < layerPlan_.persistent.size(); ++slot)
    s.layerReuse.push_back({layerPlan_.persistent[slot], s.counters.layerReused[slot], s.counters.layerComputed[slot]});
  s.idMapBytes = idMapBytes_;
  s.shadeFrame = shadeFrame_;
  s.rasterFrames = frames_;
  s.shadeFrames = shadeFrames_;
  s.chunksFilled = chunksFilled_ + (countersPending_ && !shadeFrame_ ? s.counters.chunksShaded : 0);
  s.chunksReused = chunksReused_ + (countersPending_ ? s.counters.chunksReused : 0);
  if (countersPending_ && !shadeFrame_) s.chunksFilled -= s.counters.chunksRefreshed;
  if (budget_) s.staleAge = staleAge_;
  s.msPerChunk = budget_ ? budget_->msPerChunk() : 0.0;
  return s;
}

}  // namespace sg::plugins
