// The shader interface every decoupled-shading pass shares, declared once for
// C++ (namespace sg::shader) and GLSL: the set-0 binding numbers, the
// records those bindings hold and the push-constant blocks. Each pass lists
// the bindings it uses (passes/decoupled_frame.hpp); the shader-interface test
// compiles every pass shader and checks its reflected bindings and blocks
// against that list and these records.
#ifndef SG_DECOUPLED_INTERFACE_H
#define SG_DECOUPLED_INTERFACE_H

#include "../../render/shaders/frame_interface.h"

SG_SHARED_BEGIN

// Set 0.
// 0: kBindFrame, the frame uniforms (frame_interface.h).
SG_CONST uint kBindParams = 1u;           // uniform: SgDecoupledParams
SG_CONST uint kBindObjects = 2u;          // SgDecoupledObject[]
SG_CONST uint kBindShadelInstances = 3u;  // SgShadelInstance[] (shadel_address.glsl)
SG_CONST uint kBindLevelRects = 4u;       // SgLevelRect[]
SG_CONST uint kBindRemap = 5u;            // SgRemapEntry[]
SG_CONST uint kBindOwnedEntries = 6u;     // SgOwnedEntry[]
SG_CONST uint kBindCounters = 7u;         // SgShadeCounters
SG_CONST uint kBindWork = 8u;             // the work buffer (work.glsl)
SG_CONST uint kBindArgs = 9u;             // VkDispatchIndirectCommand per object
SG_CONST uint kBindIdMaps = 10u;          // triangle-ID maps (uniform texel buffer, R32UI)
SG_CONST uint kBindVertices = 11u;        // the scene's vertices (render::GpuVertex; uniform texel buffer, RG32F)
SG_CONST uint kBindIndices = 12u;         // the scene's indices (uniform texel buffer, R32UI)
SG_CONST uint kBindLayerImage = 13u;      // the shaded layer image: storage (layer-shade) or sampled (composite)
// Of a layer's decoupled variant, after the shared ones.
SG_CONST uint kBindLayerOutput = kBindLayerImage;  // the image the layer writes
SG_CONST uint kBindLayerInputs = 14u;              // + i: the i-th layer it reads
SG_CONST uint kMaxLayerReads = 8u;
SG_CONST uint kBindLayerHistory = 22u;             // persistent layers: last frame's image of the layer
// 24..27: the frame resources a layer samples (render::kBindLayerFrameInputs).
SG_CONST uint kBindSupportMasks = 30u;             // support-expand's per-owned-entry masks
// With shading kept between frames: per physical chunk of the shade storage,
// the raster frame its shading was computed in.
SG_CONST uint kBindShadeStamps = 31u;
// Stable allocation: each owned entry's 64 chunk slots, then the free list (chunk_slots.glsl).
SG_CONST uint kBindChunkSlots = 33u;
// Which shadels of each chunk composite reads (shadel-mark's 64-bit masks, one
// per chunk slot: ownedIndex * 64 + chunk); layer-shade shades only those.
SG_CONST uint kBindShadelMasks = 34u;
// The frame's live entry blocks (live-entry-blocks): the per-entry passes'
// indirect dispatch arguments, then one SgEntryBlock per workgroup of 64.
SG_CONST uint kBindEntryBlocks = 35u;
// live-entry-blocks: per decoupled object, 1 when the occlusion cull found it
// visible, in two halves (frames of even and odd parity), persistent.
SG_CONST uint kBindObjectVisibility = 36u;
// live-entry-blocks: the frame's draw commands after the occlusion cull
// (VkDrawIndexedIndirectCommand per draw, a decoupled object's index is its
// draw's; instance count 0: culled).
SG_CONST uint kBindCulledDraws = 37u;
// The remap table (RGBA32UI: storageBase, objectInstanceId, occupancy's low
// and high word) and the shadel masks (RG32UI) as uniform texel buffers:
// shadel-mark reads them there before it sets a bit with an atomic on
// kBindRemap / kBindShadelMasks (on CPU devices a texel fetch is one gather,
// a storage-buffer read a loop over the lanes).
SG_CONST uint kBindRemapTexels = 38u;
SG_CONST uint kBindShadelMaskTexels = 39u;
// Composite's reads as uniform texel buffers, for the same reason: the level
// rectangles (RGBA32UI, SgLevelRect) and the chunk slots (R32UI).
SG_CONST uint kBindLevelRectTexels = 44u;  // 40..43, 48, 49: frame_interface.h
SG_CONST uint kBindChunkSlotTexels = 45u;
// shadel-mark-neighbours reads the shadel masks two at a time (RGBA32UI).
SG_CONST uint kBindShadelMaskPairTexels = 46u;
// shadel-mark's bilinear requests (R32UI storage image, one per pixel): what
// shadel-mark-requests turns into shadel-mask bits.
SG_CONST uint kBindMarkRequests = 47u;
// A chunk slot: the physical chunk; kNoSlot: no storage.
SG_CONST uint kNoSlot = 0xFFFFFFFFu;
SG_CONST uint kStaleAgeBins = 16u;  // SgShadeCounters.staleAgeChunks: ages 0..14, then 15 or more

SG_CONST uint kStorageCounters = 16u;      // storage partitions (they round the storage's capacity)
SG_CONST uint kMaxLevels = 16u;
SG_CONST uint kMaxPersistentLayers = 8u;

// The work buffer: per object its chunk count, the offset of its work list and
// a fill counter, then the work items {entry, chunk, level, physical chunk}.
SG_CONST uint kWorkSlotsPerObject = 3u;
SG_CONST uint kWorkSlotsPerItem = 4u;
// After the per-object slots: the reuse list's length, its first item and its
// fill counter (its items {physical chunk, physical chunk, -, -} follow the
// shade items: what shade-reuse copies in kept layers' image pairs), and one spare slot.
SG_CONST uint kWorkGlobalSlots = 4u;

// One decoupled object (all its primitives share one material).
struct SgDecoupledObject {
  mat4 world;
  uint firstIndex;     // into the scene index buffer
  int vertexOffset;
  uint triangleCount;
  uint material;
  uint idMapOffset;    // first texel of level 0 in the ID-map buffer
  uint shadingUvSet;   // 0 or 1
  vec2 tileOffset;     // shading UV = uv - tileOffset
  uint supportChunks;  // support-expand grows its marked chunks by this many (0: no neighbourhood layer)
  uint reuse;          // 1: chunks it marked last frame too keep their stored shading (not shaded)
  uint keepLayers;     // bit p: its view-independent layer in persistent slot p keeps last frame's values (layer_rate.hpp)
  uint pad2;  // 112 bytes, as std430 laid it out: every record's mat4 stays 16-byte aligned
};

// What the passes count, read back after the frame.
struct SgShadeCounters {
  uint chunksMarked;
  uint chunksAllocated;
  uint overflowChunks;
  uint compositeMisses;
  uint coveredPixels;                // fragments composite wrote
  uint levelChunks[kMaxLevels];      // marked chunks per detail level
  uint supportChunks;                // chunks support-expand added around the marked ones
  uint layerReused[kMaxPersistentLayers];    // per persistent layer: shadels served from last frame
  uint layerComputed[kMaxPersistentLayers];  // and shadels computed
  uint chunksShaded;                 // chunks the layers shaded this frame (all of them on a shade frame)
  uint chunksReused;                 // chunks that kept their stored shading instead
  uint staleMaxAge;                  // raster frames since the oldest reused chunk was shaded (0: none reused)
  uint chunksRefreshed;              // chunks that could have been reused but were shaded for their age (budget mode)
  uint staleAgeChunks[kStaleAgeBins];  // reusable chunks by the age they would have if reused (budget mode)
  uint shadelsSkipped;               // shadels of shaded chunks layer-shade left out: no pixel reads them
  // Owned entries the per-entry passes visited (counted by shadel-clear's
  // entry step: live spans, or with the occlusion-culled skip the live entry
  // blocks), and in how many workgroups of 64.
  uint entriesVisited;
  uint entryGroupsVisited;
};

// The frame's parameters (uniform).
struct SgDecoupledParams {
  float bias;                 // global fractional level bias (the adjuster's)
  uint entriesPerSideLog2;    // virtual sheet
  uint storageWidthChunks;    // layer image width in chunks
  uint ownedEntryCount;
  uint objectCount;
  uint workCapacity;          // work items the work buffer holds
  uint frameNumber;           // this raster frame's number (shade stamps)
  // Budget mode (0: off): a reusable chunk older than this many raster frames
  // is shaded instead; one exactly this old is when a hash of its place falls
  // below staleAgeFraction (of 65536).
  uint staleAgeLimit;
  uint stampsBound;           // 1: the shade-stamp buffers are bound (shading kept between frames)
  uint staleAgeFraction;
};

// Push constants of a layer's decoupled variant (layer-shade).
struct SgLayerShadePush {
  uint objectIndex;
  uint persistentSlot;   // the layer's slot in SgShadeCounters.layerReused/Computed
  uint historyValid;     // last frame's remap and layer image describe this storage layout
  uint shadelMasks;      // 1: shade only the shadels shadel-mark marked (DecoupledFrame::shadelMasks)
  uint countSkipped;     // 1: this step counts the shadels it leaves out (the material's last layer)
};

// Push constants of the passes that run per owned remap entry (shadel-clear,
// shadel-allocate, work-fill, shadel-gutter, support-expand, shade-frame):
// the owned entries [begin, end) this dispatch covers, one run of the frame's
// live entries (sg::shadel::liveEntrySpans; entry_span.glsl). With `blocks`
// 1, an indirect dispatch over the frame's live entry blocks instead
// (kBindEntryBlocks): each workgroup finds its entries there.
struct SgEntrySpan {
  uint begin;
  uint end;
  uint blocks;
};

// The live entry blocks buffer (kBindEntryBlocks): indirect dispatch
// arguments for the per-entry passes with 64 and with 32 entries per
// workgroup, then the blocks. A block is up to 64 owned entries of a live
// span, [first, first + 64) cut at the span's end.
SG_CONST uint kEntryBlockSize = 64u;
SG_CONST uint kMaxBlockSpans = 8u;  // sg::shadel::kMaxLiveSpans
struct SgEntryBlock {
  uint first;
  uint spanEnd;
};
struct SgEntryBlocksHeader {
  uint args64[3];  // VkDispatchIndirectCommand: a workgroup per block
  uint args32[3];  // two per block
  uint blockCount;
  uint pad;
};

// Push constants of live-entry-blocks: the frame's live spans (CPU: objects
// shaded now or last frame) and what the occlusion cull adds.
struct SgEntryBlocksPush {
  SgEntrySpan spans[kMaxBlockSpans];  // .blocks: the span's first candidate block
  uint spanCount;
  uint candidateBlocks;  // blocks of 64 over all spans
  uint objectCount;
  uint parity;           // this frame's half of the visibility buffer
  uint historyValid;     // 1: the other half holds last frame's visibility
  uint culled;           // 1: the draw commands hold this frame's occlusion cull (else all visible)
};

// Push constants of the occupancy debug view: the sheet window it shows.
struct SgOccupancyPush {
  uvec2 originChunks;
  uvec2 sizeChunks;
};

SG_SHARED_END

#endif
