#pragma once
// Decoupled shading (Baker & Jarzynski 2022): what its passes (registered by
// decoupled_package.cpp) share within a frame and keep across frames. Each
// frame, prepare() gives shadel space to objects newly switched to decoupled
// and takes it back from those switched away, runs the global shade-space
// adjuster on the last frame's counters, takes this frame's decoupled draws
// from the forward list, and declares the frame's shadel resources. Owns the
// virtual shadel space, the remap table, the triangle-ID maps and the tables
// the passes read.
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/buffer_view.hpp>
#include <decoupled_frame.hpp>
#include <shadelgraph/render/frame_context.hpp>
#include <shadelgraph/shadel/live_entry_spans.hpp>
#include <shadelgraph/shadel/shadel_space.hpp>
#include <shadelgraph/shadel/shadel_storage.hpp>
#include <shadelgraph/shadel/unmipmapped_minification.hpp>

#include "chunk_slots.hpp"
#include "decoupled_tables.hpp"
#include "layer_history.hpp"
#include "layer_plan.hpp"
#include "shade_budget.hpp"
#include "shade_space_adjuster.hpp"
#include "shading_choice.hpp"

namespace sg::plugins {

// What the frame shows: the shaded image, or a debug view of decoupled shading.
enum class DebugView { Final, Level, Occupancy, Sheet };

// An object in mode auto is shaded forward while its bounding sphere's
// projected radius is below this many pixels: too small to pay for its chunks.
inline constexpr float kTinyObjectPixels = 8.0f;

// Shade storage is this much larger in frames where a visible material reads
// a neighbourhood (support-expand marks a ring of chunks around what is seen).
inline constexpr double kSupportStorageScale = 2.0;

struct DecoupledSettings {
  uint32_t sheetSizeLog2 = 16;  // 64K x 64K virtual shadels; up to 19 (512K)
  double storageFactor = shadel::kDefaultStorageFactor;  // shade storage = factor x output pixels
  uint32_t storageChunks = 0;  // when non-zero, the shade storage in chunks regardless of the output (tests)
  int filter = 1;                      // composite (and what shadel-mark marks): 0 point, 1 bilinear (default: the most accurate, issue 14), 2 trilinear
  bool baseline = false;           // bench --baseline: shadel-mark as before issue 14
  // Shade only the shadels composite reads (passes::DecoupledFrame::shadelMasks, where it applies); false: whole chunks.
  bool shadelMasks = true;
  // With the bilinear filter and shadel masks the depth pre-pass writes
  // shadel-mark's requests (passes::markRequestsPossible); false: shadel-mark
  // rasterizes the objects again and marks with atomics (the same images;
  // tests compare the two).
  bool markRequests = true;
  // Invocations of a layer-shade workgroup (8 to 64, each shading 64 / n
  // shadels of its chunk); 0: the device's subgroup size. The images do not
  // depend on it; tests compare the shapes.
  uint32_t layerShadeInvocations = 0;
  std::optional<float> fixedBias;      // else the adjuster decides
  // A shade frame (every marked chunk shaded) every this many raster frames;
  // in the others only chunks without valid shading from the last frame are
  // shaded (the fill), the rest copied. 1: every frame a shade frame.
  uint32_t shadeRate = 1;
  // Frames in flight (issue 15): with a shade rate above 1 the shade frame
  // runs after its raster frame's composite, as the frame's tail on async
  // compute, and later raster frames read it; every raster frame reuses and
  // fills. The renderer must run 2 frames in flight for it to overlap.
  bool overlap = false;
  // Budget mode (shade_budget.hpp), instead of shade frames: each frame fills
  // what is missing and reshades the stalest reusable chunks this many
  // milliseconds of layer shading afford (by the cost per chunk measured
  // through observeTimings, else budgetMsPerChunk).
  std::optional<double> shadeBudgetMs;
  double budgetMsPerChunk = kInitialMsPerChunk;
  // View-independent layers keep their values across shade frames (layer_rate.hpp); false: computed
  // whenever their chunk is shaded, as view-dependent ones (bench comparisons).
  bool keepViewIndependentLayers = true;
  // Level 0 at least the screen's rate in the view that first shows each
  // object (shadel::screenRateLevel0Size); false: from textures and triangle
  // count only, as before (comparisons).
  bool screenRateLevel0 = true;
  // Mode auto draws an object forward in frames where a texture it samples
  // without mip levels is minified (shadel/unmipmapped_minification.hpp);
  // false: decoupled there, as before (comparisons).
  bool forwardMinifiedUnmipmapped = true;
  // The per-entry passes visit only the owned entries of objects shaded this
  // frame or still holding stored chunks (shadel::liveEntrySpans); false:
  // every allocated object's, culled or not, as before (comparisons).
  bool liveEntrySpans = true;
  // Within those spans, the per-entry passes also skip the entries of objects
  // the occlusion cull hid this frame and last frame, decided on the GPU
  // (passes::addLiveEntryBlocks: indirect dispatches over the visited blocks
  // of 64 entries); false: every entry of the spans (comparisons).
  bool skipOccludedEntries = true;
  DebugView view = DebugView::Final;
  ShadeSpaceAdjusterOptions adjuster;
};

// A persistent layer's shadels of the last frame: served from the frame before, or computed.
struct LayerReuse {
  std::string layer;
  uint64_t reused = 0, computed = 0;
};

struct DecoupledStats {
  ShadeCounters counters{};  // of the last executed frame
  float bias = 0.0f;         // the bias that frame was rendered with
  uint32_t objects = 0;  // shaded decoupled in that frame
  uint32_t capacityChunks = 0;
  uint64_t storageBytes = 0;  // shade storage, per layer
  uint64_t remapBytes = 0;
  uint64_t idMapBytes = 0;
  uint64_t historyBytes = 0;  // persistent layers' images and last frame's remap
  uint32_t layerDispatches = 0;  // indirect layer-shade dispatches of the frame
  bool markedByRequests = false;  // the depth pre-pass wrote shadel-mark's requests (DecoupledFrame::markRequests)
  // Owned remap entries allocated, and those the per-entry passes visited in
  // that frame (live spans), in how many runs (dispatches per such pass).
  uint32_t ownedEntries = 0, liveEntries = 0, liveSpans = 0;
  // The entries they did visit, counted on the GPU (fewer than liveEntries
  // when the occlusion-culled skip left blocks out; a block's whole span
  // part when not), and in how many workgroups of 64.
  uint32_t visitedEntries = 0, visitedEntryGroups = 0;
  std::vector<std::string> layers;  // layers the frame ran decoupled, in pass order
  std::vector<LayerReuse> layerReuse;  // per persistent layer
  bool shadeFrame = true;  // the last frame was a shade frame
  // Since the first frame (the last one included): raster frames, how many of
  // them were shade frames, chunks shaded in the others because they had no
  // valid shading (the fill), and chunks copied from the frame before.
  uint64_t rasterFrames = 0, shadeFrames = 0, chunksFilled = 0, chunksReused = 0;
  // Budget mode: the age limit the last frame ran with (kReuseAnyAge: none)
  // and the cost per chunk it was chosen by.
  StaleAgeLimit staleAge;
  double msPerChunk = 0.0;
};

class DecoupledShading {
 public:
  // `choices`: per scene instance, whether it can be shaded decoupled (its chart).
  DecoupledShading(std::vector<ShadingChoice> choices, DecoupledSettings settings = {});
  ~DecoupledShading();

  // Once per frame, from any decoupled pass's prepare step.
  void prepare(render::FrameContext& ctx);
  // Does this frame shade objects decoupled / has it allocated objects at all?
  bool shading() const { return !frameObjects_.empty(); }
  bool overlapping() const { return settings_.overlap && settings_.shadeRate > 1; }
  bool hasObjects() const { return allocatedObjects_ > 0; }
  bool needsSupport() const { return layerPlan_.needsSupport; }
  // This frame's shared state, its resources synchronised with the frame
  // resources `shadel.*` (a user's pass may have given them new versions).
  passes::DecoupledFrame& frame(render::FrameContext& ctx);
  // Publishes the frame's current versions of these `shadel.*` resources.
  void publish(render::FrameContext& ctx, std::initializer_list<const char*> resources);
  // One layer-shade pass per depth of the frame's layer plan.
  void addLayerPasses(graph::RenderGraph& graph, const plugin::Registry& materials, const std::string& prefix = "");
  void addCountersReadback(graph::RenderGraph& graph);
  // With skipOccludedEntries: the live-entry-blocks pass before the first per-entry pass (frame.entryBlocks).
  void addLiveEntryBlocks(render::FrameContext& ctx);
  // With `overlap`, in a shade frame: its own work list of every stored chunk
  // and the layer passes over it, after composite (the frame's tail).
  void addShadeFrameTail(graph::RenderGraph& graph, const plugin::Registry& materials);
  // This frame's composite filter instead of the setting (composite's
  // `filter` parameter): from a prepare step, before any pass declares.
  void setFrameFilter(render::FrameContext& ctx, int filter);
  // shadel-mark's declare: the requests the depth pre-pass wrote, if it drew
  // the decoupled objects (offerDepthPassDraws), become frame().markRequests.
  void takeMarkRequests(render::FrameContext& ctx);
  // From the next frame on: a fixed bias, or the adjuster's (empty).
  void setFixedBias(std::optional<float> bias);
  const DecoupledSettings& settings() const { return settings_; }
  // A finished frame's timings: budget mode learns the layer-shade cost per chunk from them.
  void observeTimings(const gpu::FrameTimings& timings);
  glm::uvec2 sheetRegionOrigin() const { return sheetRegionOrigin_; }
  glm::uvec2 sheetRegionSize() const { return sheetRegionSize_; }

  // Reads the counters of the last executed frame (call after it completed).
  DecoupledStats stats() const;
  // Where each chunk stored after the last frame is (stable allocation), by
  // entry index * 64 + chunk; reads the GPU's chunk slots (call after the frame completed).
  std::map<uint64_t, uint32_t> chunkAddresses(gpu::Device& device) const;
  const std::vector<ShadingChoice>& choices() const { return choices_; }
  // Draws of objects the choices took that still stay forward, and why: what
  // only running finds out (no room for the triangle-ID map, no shadel space,
  // forward-only material layers). Valid after a frame.
  struct RunTimeForward {
    uint32_t instance = 0;
    uint32_t primitive = 0;
    std::string reason;
  };
  std::vector<RunTimeForward> runTimeForward() const;
  // Decoupled objects in mode auto drawn forward in the last frame, and why
  // (tiny on screen; a texture without mip levels minified: unmipmapped_minification.hpp).
  const std::vector<RunTimeForward>& frameForward() const { return frameForward_; }
  // Triangle-ID maps made coarser than their object asked for so that all fit
  // the one buffer (id_map_budget.hpp): that object shades at most this fine.
  struct ShrunkIdMap {
    uint32_t instance = 0;  // the first object that asked for the map (instances of one mesh share it)
    uint32_t primitive = 0;
    uint32_t wantedLevel0 = 0, level0 = 0;  // level-0 size asked for, and given
    uint64_t bufferBytes = 0;               // the buffer all maps share (maxStorageBufferRange)
  };
  const std::vector<ShrunkIdMap>& shrunkIdMaps() const { return shrunkIdMaps_; }

 private:
  // Where shadel-mark's requests apply, hands the depth pre-pass the decoupled
  // draws (render::DepthPassDraws), so they are rasterized once less; else
  // takes the offer back.
  void offerDepthPassDraws(render::FrameContext& ctx);
  void createTables(gpu::Device& device);
  // Gives shadel space to draws whose object now asks for decoupled, releases the rest.
  void syncObjects(const render::FrameContext& ctx);
  // This frame's decoupled objects (frameDraws_, frameObjects_, frameMaterials_), taken from ctx's forward draws.
  void selectFrameObjects(render::FrameContext& ctx);
  void uploadTables(gpu::Device& device);
  // Which objects may keep last frame's shading this frame (their records' `reuse`);
  // writes every record to the GPU.
  // Also which view-independent layers each object keeps (layer_rate.hpp).
  void chooseReuse(bool historyValid, const plugin::Registry& materials);
  // A stored shadel holds its shadows: an object is treated as changed this
  // frame when a shadowed light that reaches it got or lost its maps, or when
  // a caster of such a light moved and its shadow (where it was or where it
  // is) may fall on the object.
  void markShadowChanges(const render::FrameContext& ctx);

  std::vector<ShadingChoice> choices_;
  DecoupledSettings settings_;
  ShadeSpaceAdjuster adjuster_;
  float bias_ = 0.0f;
  float lastFrameBias_ = 0.0f;
  uint64_t frames_ = 0;
  uint64_t preparedFrame_ = ~0ull;
  bool shadeFrame_ = true;     // this frame shades every marked chunk
  bool reuseAny_ = false;      // some object may reuse this frame: shade-reuse runs
  bool countersPending_ = false;  // the readback holds counters not yet in the totals below
  std::optional<ShadeBudget> budget_;
  StaleAgeLimit staleAge_;  // this frame's (params.staleAgeLimit and staleAgeFraction)
  uint64_t rasterFrames_ = 0, shadeFrames_ = 0, chunksFilled_ = 0, chunksReused_ = 0;  // before the last frame
  // Per draw (a decoupled object's index is its draw's): its shadel space and
  // tables, while its object is decoupled.
  struct ObjectSlot {
    uint32_t instance = 0;
    uint32_t primitive = 0;
    bool allocated = false;
    std::string reason;  // why not, when it asked to be
    DecoupledObject record{};
    uint32_t levelRule = 0;  // how its level follows its footprint (shadel::packLevelRule): a pipeline variant
    shadel::UnmipmappedTexels unmipmapped;  // its finest texture without mip levels (auto: forward where minified)
    std::string materialStack;  // the material its stored shading was shaded with
    uint64_t changedFrame = 0;  // the frame it was allocated, moved or changed material: nothing to reuse then
    uint64_t materialFrame = 0;  // the frame it was allocated or changed material (its kept layers are recomputed)
    // Its material reads neighbours or its own last value: those inputs must be
    // around and under every chunk each frame, so it is reshaded whole.
    bool reshadedWhole = false;
  };
  std::vector<ObjectSlot> slots_;
  std::vector<glm::mat4> lastWorlds_;    // per draw: its world matrix last frame (markShadowChanges)
  std::vector<glm::vec4> lastSpheres_;   // per draw: its bounding sphere last frame
  std::vector<bool> lastShadowed_;       // per light: it had shadow maps last frame
  uint32_t allocatedObjects_ = 0;
  std::vector<uint32_t> identity_;  // draw index -> object index (the same)
  std::vector<uint32_t> levelRules_;  // this frame's, by object index (DecoupledFrame::levelRules)
  std::map<std::pair<int, uint32_t>, std::pair<shadel::DetailLevels, uint32_t>> idMaps_;  // by mesh and primitive: levels, ID-map offset
  std::set<std::pair<int, uint32_t>> noIdMapRoom_;  // primitives whose map would not fit the ID-map buffer
  std::vector<ShrunkIdMap> shrunkIdMaps_;
  std::vector<uint32_t> idTexels_;
  bool tablesDirty_ = true;
  // This frame: the objects shaded decoupled (draws = ids, materials).
  std::vector<uint32_t> frameObjects_;
  std::vector<std::string> frameMaterials_;
  std::vector<RunTimeForward> frameForward_;  // allocated objects drawn forward this frame (mode auto)
  LayerPlan layerPlan_;
  LayerHistory history_;
  LayerHistory::Declared declaredHistory_;
  std::optional<passes::DecoupledFrame> frame_;
  graph::ResourceHandle readbackHandle_;
  std::unique_ptr<shadel::ShadelSpace> space_;
  uint32_t ownedEntryCount_ = 0;
  std::vector<shadel::EntrySpan> ownedRuns_;  // per object (instance id): its owned entries
  shadel::LiveInstances liveInstances_;       // shaded this frame or holding stored chunks
  std::vector<shadel::EntrySpan> liveSpans_[2];  // the frame's (DecoupledFrame::liveSpans), per frame in flight
  // Per object, its occlusion-cull visibility in the last two frames (live-entry-blocks), and the
  // frame that last wrote it (0: none since it was made or the tables changed).
  gpu::Buffer objectVisibility_;
  uint64_t visibilityFrame_ = 0;
  bool blocksWanted_ = false;  // this frame: skipOccludedEntries, and the spans are not every entry
  ChunkSlots chunkSlots_;  // stable allocation: where each stored chunk is, kept across frames
  shadel::StorageLayout storage_;
  uint64_t idMapBytes_ = 0;
  glm::uvec2 sheetRegionOrigin_{0}, sheetRegionSize_{1};  // allocated part of the sheet, in chunks
  uint64_t remapBytes_ = 0;
  // Written by the host every frame: one per frame in flight (a shade frame
  // left running reads its own while the next frame is prepared).
  gpu::Buffer params_[2], objects_[2];
  uint32_t ring() const { return uint32_t(frames_ % 2); }
  gpu::Buffer shadelInstances_, levelRects_, ownedEntries_, idMapBuffer_, readback_;
  gpu::BufferView idMapTexels_;  // idMapBuffer_ as R32UI texels, for layer shading
};

}  // namespace sg::plugins
