#pragma once
// What the decoupled-shading passes of one frame share: the static tables the
// host uploaded (objects, shadel-space rectangles, owned remap entries,
// triangle-ID maps), the per-frame parameters, and the graph resources the
// passes hand to each other. The decoupled package (plugins/decoupled) fills
// it. The binding numbers and records are the shared shader interface
// (framework/shadel/shaders/decoupled_interface.h).
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/render/scene_view.hpp>
#include <shadelgraph/shadel/shaders/decoupled_interface.h>

namespace sg {
class PassContext;
}

namespace sg::passes {

using namespace shader;  // kBind*, the records

struct DecoupledFrame {
  render::SceneView view;               // view.draws: the draws of the objects shaded decoupled this frame
  std::span<const uint32_t> objectIds;  // their decoupled object index, one per view.draws entry
  std::span<const uint32_t> objectDraws;  // every decoupled object's draw, by object index (materials)
  // Every decoupled object's level rule (shadel::packLevelRule), by object
  // index; empty: all 0 (the isotropic level). A pipeline variant of
  // shadel-mark and composite (levelRuleDefines), chosen per draw.
  std::span<const uint32_t> levelRules;
  const gpu::Buffer& params;
  const gpu::Buffer& objects;
  const gpu::Buffer& shadelInstances;
  const gpu::Buffer& levelRects;
  const gpu::Buffer& ownedEntries;
  VkBufferView idMaps;  // the triangle-ID maps as R32UI texels (a uniform texel buffer: one gather per read on CPU devices)
  uint32_t ownedEntryCount = 0;
  uint32_t objectCount = 0;
  // The owned entries the per-entry passes visit this frame, as runs
  // (sg::shadel::liveEntrySpans): those of the objects shaded this frame and
  // of those still holding stored chunks. Culled objects' entries are left
  // alone. Empty: those passes dispatch nothing.
  std::span<const SgEntrySpan> liveSpans;
  // With the occlusion-culled skip (live-entry-blocks): the blocks of the
  // live spans whose objects the cull did not hide this frame and last frame,
  // and their indirect dispatch arguments; the per-entry passes dispatch
  // those instead of the spans. Invalid: the spans.
  graph::ResourceHandle entryBlocks;
  // The composite filter (0 point, 1 bilinear, 2 trilinear), which is also
  // what shadel-mark marks: both pipelines get it only as filterDefine(filter).
  // Settled in the prepare step (the renderer's setting or composite's
  // `filter` parameter), before any pass declares.
  int filter = 1;
  int markedFilter = -1;  // the filter shadel-mark was declared with (composite checks it); -1: none yet
  bool baseline = false;  // bench --baseline only: shadel-mark as before issue 14
  bool levelView = false;  // composite shows the detail level instead of the shading
  // Invocations of a layer-shade workgroup (8 to 64; chunkRowsPerInvocation);
  // 0: the device's subgroup size.
  uint32_t layerShadeInvocations = 0;
  graph::ResourceHandle remap, counters, work, args;
  graph::ResourceHandle shadedColor;  // what composite filters: the last layer of every material writes it
  // Stable allocation: each owned entry's chunk slots and the free list
  // (chunk_slots.glsl), persistent across frames.
  graph::ResourceHandle slots;
  // With shading kept between frames: when each stored chunk's shading was
  // computed (u32 raster frame per physical chunk); invalid otherwise
  // (params.stampsBound 0: not read).
  graph::ResourceHandle stamps;
  // Shadel masks (issue 14): shadel-mark also marks which shadels of each
  // chunk composite's footprints read (one 64-bit mask per chunk slot), and
  // layer-shade shades only those, except for objects whose material reads a
  // neighbourhood (support-expand: whole chunks). Off (whole chunks) where a
  // shadel's stored value may be served in a later frame: shading kept between
  // frames, persistent or view-independent layers; for bench --baseline and
  // the sheet debug view.
  bool shadelMasks = false;
  graph::ResourceHandle masks;  // valid when shadelMasks, from shadel-mark on
  // The per-pixel mark requests the depth pre-pass wrote (R32UI: a mask slot
  // and box, shadel_box.glsl; shadel-mark's markRequestsPossible), which
  // shadel-mark-requests turns into mask bits; invalid: shadel-mark rasterizes.
  graph::ResourceHandle markRequests;
  // The pixels the decoupled draws can cover (x0, y0, x1, y1, end exclusive;
  // render::boxScreenRect of their world boxes): shadel-mark-requests merges
  // only there (on lavapipe a compute shader pays for empty pixels too).
  int32_t cover[4] = {0, 0, INT32_MAX, INT32_MAX};
};

// The define shadel-mark and composite are both compiled with: the filter
// (SG_FILTER_* of shadel_level.glsl). Throws for a filter outside 0..2.
std::pair<std::string, std::string> filterDefine(int filter);
// The defines of the shadel-mark and composite variant for objects with
// level rule `levelRule` (shadel::packLevelRule; shadel::levelRuleDefines):
// none for rule 0, so objects without one keep the shaders of before the
// rule and pay nothing for it.
std::vector<std::pair<std::string, std::string>> levelRuleDefines(uint32_t levelRule);
// What names a level rule's pipeline variant: "" for rule 0, else "/rule-<hex word>".
std::string levelRuleVariant(uint32_t levelRule);

// The set-0 layout of a decoupled pass whose shaders use the shared
// `bindings`; the layer image is a storage image when `layerImageStorage`,
// else sampled.
gpu::PipelineLayoutDesc decoupledLayout(std::span<const uint32_t> bindings, bool layerImageStorage = false,
                                        uint32_t pushConstantBytes = 0,
                                        std::initializer_list<VkDescriptorSetLayout> extraSets = {});
// Binds `pipeline` with the descriptors of `bindings` from the frame, and the
// pass's own `extra` ones.
void bindDecoupled(PassContext& ctx, const gpu::Pipeline& pipeline, const DecoupledFrame& frame,
                   std::span<const uint32_t> bindings, std::span<const gpu::DescriptorWrite> extra = {});

// One dispatch of the bound per-entry `pipeline` per live span, each
// (span length / entriesPerGroup) workgroups as a 2D grid, its span pushed
// (SgEntrySpan, entry_span.glsl); nothing for an empty span. With the frame's
// entry blocks, one indirect dispatch over them instead. entriesPerGroup: 64 or 32.
void dispatchEntrySpans(PassContext& ctx, const gpu::Pipeline& pipeline, const DecoupledFrame& frame,
                        uint32_t entriesPerGroup = 64);
// Declares what dispatchEntrySpans reads: the frame's entry blocks, if any.
void readEntryBlocks(graph::Pass& pass, const DecoupledFrame& frame);

// Draws the frame's decoupled objects as their decoupled object ids (culled
// by `indirect` when set): the opaque ones with pipeline(false, rule), then the
// alpha-mask ones with pipeline(true, rule), their alpha-tested variant, whose
// set 1 is the draw's scene material; within each, the objects without a level
// rule (0) first, then those of each rule (DecoupledFrame::levelRules). Set 0
// is bound for each pipeline from `bindings`. `reverseOpaque`: the opaque
// draws in the opposite order (composite, and shadel-mark's requests in the
// depth pre-pass: of opaque fragments tied in depth both keep the first, so
// across draws the one forward's last-drawn-wins keeps; alpha-tested ones,
// whose fragments may be cut away after the depth test, keep the last).
void drawDecoupled(PassContext& ctx, const DecoupledFrame& frame, std::span<const uint32_t> bindings, VkBuffer indirect,
                   const std::function<const gpu::Pipeline&(bool alphaTest, uint32_t levelRule)>& pipeline,
                   bool reverseOpaque = false);

}  // namespace sg::passes
