#version 460
// Marks the chunks composite will read for this pixel: at each level the
// composite filter (SG_FILTER, the same define composite is compiled with)
// reads (sgSelectFilterLevel: the nearest for point and bilinear, fine and
// coarse for trilinear), the chunk of the footprint's top-left tap, whose
// tile in shade storage (the chunk and a one-shadel gutter) holds the whole
// footprint. One remap read per level, an atomic only when the bit is missing
// (with SG_MARK_OWN_CHUNK_ONLY, below, neither).
// With SG_SHADEL_MASKS it also marks which shadels of the chunk the footprint
// reads (layer-shade shades only those), and of each neighbour chunk whose
// first row or column fills the tile's gutter.
// With SG_MARK_OWN_CHUNK_ONLY (masks, bilinear or trilinear) it sets only
// the mask of the footprint's own chunk: the chunk's occupancy bit and what
// the neighbours' first column / row give the gutter follow from the masks
// in a compute step after the draws (shadel_mark_neighbours.comp), which
// spares every pixel the occupancy's read and atomic and the loop over
// neighbour chunks.
// Early depth test: hidden surfaces mark nothing. No colour output, but with
// SG_MARK_REQUESTS (bilinear with masks), where the depth pre-pass draws the
// decoupled objects with this shader (render::DepthPassDraws): it writes the
// pixel's request instead of marking, and the fragment that keeps the depth
// keeps the pixel's request.
//
// Cost on lavapipe: every buffer read or atomic in a fragment shader is a
// loop over the 8 lanes, whether or not a lane takes its branch (an `if` is
// only a mask). So the shader keeps few of them in its code: the levels come
// flat from the vertex shader, a level's rectangle through a texel view (a
// gather), and the chunks a footprint touches are marked
// in one loop that runs as often as the lane with the most chunks needs.
#include <framework/render/shaders/object.glsl>
#include <framework/shadel/shaders/decoupled.glsl>
#include <passes/shadel-mark/shadel_mark_levels.glsl>
#include <passes/shadel-mark/shadel_box.glsl>

#ifndef SG_FILTER
#error "SG_FILTER: the composite filter (passes::filterDefine)"
#endif

#if defined(SG_MARK_REQUESTS) && defined(SG_ALPHA_TEST)
// In the depth pre-pass (SG_MARK_REQUESTS) the fragment writes depth: where
// the alpha test cuts it away it must not, so the depth test comes after.
#else
layout(early_fragment_tests) in;
#endif
layout(location = 0) in vec2 inShadingUv;

#ifdef SG_ALPHA_TEST
// Alpha-mask objects: the pixels their alpha test cuts away (the z-prepass
// gave them no depth there) neither mark nor composite.
#include <passes/alpha-mask/alpha_test.glsl>
layout(location = 1) in vec2 inUv0;
layout(location = 2) in vec2 inUv1;
layout(location = 3) in float inColorAlpha;
#endif

#ifdef SG_MARK_BASELINE
// The mark before issue 14 (bench --baseline only): the trilinear footprint
// whatever the filter, one remap read per tap. It marks the levels composite
// reads: for point and bilinear that is now one (the nearest), so the
// baseline compares the marking code, not the level choice.
void markShadel(uvec2 shadel) {
  SgShadelAddress a = sgShadelAddress(shadel, params.entriesPerSideLog2);
  uint64_t bit = sgChunkBit(a.chunkIndex);
  if ((remap[a.entryIndex].occupancy & bit) == uint64_t(0)) atomicOr(remap[a.entryIndex].occupancy, bit);
}

void markLevel(uint level) {
  SgLevelRect rect = sgLevelRect(object.objectId, level);
  SgBilinearTaps taps = sgBilinearTaps(inShadingUv, rect.size);
  for (uint i = 0u; i < 4u; ++i) markShadel(sgFootprintShadel(rect, taps, i));
}

const bool kMarkCoarse = true;
#else
layout(location = kMarkLevelsLocation) flat in uvec4 inLevels;  // level0Size, levelCount, firstOwnedEntry, firstLevelRect
layout(set = 0, binding = kBindLevelRectTexels) uniform usamplerBuffer levelRectTexels;  // RGBA32UI: SgLevelRect

// The tables' bits are read through texel views of the buffers the atomics
// write (a gather on lavapipe, where a storage-buffer read is a loop over the
// lanes). A read may miss a bit another invocation of this pass has just set
// (bits are only ever set here): that costs one redundant atomic, never a
// missing mark.
#ifndef SG_MARK_OWN_CHUNK_ONLY  // (glslang emits uncalled functions: the remap must not be in the interface)
layout(set = 0, binding = kBindRemapTexels) uniform usamplerBuffer remapTexels;  // RGBA32UI: .zw the occupancy

// Sets the chunk's bit in its remap entry's occupancy unless it shows set.
void sgMarkChunk(SgShadelAddress a) {
  uint64_t bit = sgChunkBit(a.chunkIndex);
  if ((packUint2x32(texelFetch(remapTexels, int(a.entryIndex)).zw) & bit) == uint64_t(0))
    atomicOr(remap[a.entryIndex].occupancy, bit);
}
#endif

#ifdef SG_SHADEL_MASKS
#ifdef SG_MARK_REQUESTS
layout(location = 0) out uint outRequest;  // R32UI, cleared to 0: no request
#else
layout(set = 0, binding = kBindShadelMasks, std430) buffer ShadelMasks { uint64_t shadelMasks[]; };
layout(set = 0, binding = kBindShadelMaskTexels) uniform usamplerBuffer shadelMaskTexels;  // RG32UI

// Sets `bits` of chunk slot `slot`'s shadel mask unless they all show set.
void sgMarkShadels(uint slot, uint64_t bits) {
  if ((packUint2x32(texelFetch(shadelMaskTexels, int(slot)).xy) & bits) != bits) atomicOr(shadelMasks[slot], bits);
}
#endif

#ifdef SG_MARK_OWN_CHUNK_ONLY
// What composite reads of the tile, bilinear or trilinear: the 2x2 taps at
// (tile & 7) + {0,1}², of which this marks the part inside the tile's own
// chunk (lo..min(lo + 1, 7)), whatever their weight (a weight-0 tap is still
// fetched). The part in the gutter (the next chunks' first column / row)
// shadel_mark_neighbours.comp derives from these masks after the draws.
// With SG_MARK_REQUESTS (bilinear: one footprint a pixel) it writes the mask
// slot and lo as this pixel's request instead (shadel_box.glsl), and
// shadel_mark_requests.comp sets the bits after the depth pre-pass: no atomic
// here, whose loop over the lanes lavapipe runs in every group, needed or not.
void markFootprint(SgMarkLevel level, SgBilinearTaps taps, uvec2 tile) {
  uvec2 inChunk = tile & (SG_CHUNK_SIZE - 1u);
  uvec2 chunkOrigin = tile - inChunk;
  uint slot = sgMarkStorageBase(level, chunkOrigin) + sgShadelAddress(chunkOrigin, params.entriesPerSideLog2).chunkIndex;
#ifdef SG_MARK_REQUESTS
  outRequest = sgMarkRequest(slot, inChunk);
#else
  sgMarkShadels(slot, sgBoxBits(inChunk, min(inChunk + 1u, uvec2(SG_CHUNK_SIZE - 1u))));
#endif
}
#else
// What composite reads of the tile: the footprint's taps at (tile & 7) +
// [lo, hi] in the 9x9 tile, whatever their weight (a weight-0 tap is still
// fetched). Point: the nearest tap only; bilinear, trilinear: the 2x2. The
// tile's own chunk gets the part inside it; each neighbour chunk (right,
// below, diagonal) whose first column / row fills the gutter the footprint
// reaches gets that part when it is inside the level (else the gutter repeats
// the tile's own edge shadels, which the clamped own box holds). Each
// chunk's shadel mask (slot storageBase + chunk, the storageBase
// shadel-clear gives the entry: sgMarkStorageBase) is read first and set only when bits
// are missing.
void markFootprint(SgMarkLevel level, SgBilinearTaps taps, uvec2 tile) {
  SgLevelRect rect = level.rect;
  uvec2 inChunk = tile & (SG_CHUNK_SIZE - 1u);
  uvec2 lo = inChunk, hi = inChunk + 1u;
  if (SG_FILTER == SG_FILTER_POINT) {
    lo += uvec2(greaterThanEqual(taps.weight, vec2(0.5)));
    hi = lo;
  }
  uvec2 last = uvec2(SG_CHUNK_SIZE - 1u);
  uvec2 chunkOrigin = tile - inChunk;
  // Inside the level: the right, lower and diagonal neighbour chunks.
  bvec2 nextInside = lessThan(chunkOrigin + SG_CHUNK_SIZE - rect.origin, uvec2(rect.size));
  // Bit 0 the own chunk, 1 right, 2 below, 3 diagonal: the chunks to mark.
  uint chunks = 1u;
  if (hi.x == SG_CHUNK_SIZE && lo.y <= last.y && nextInside.x) chunks |= 2u;
  if (hi.y == SG_CHUNK_SIZE && lo.x <= last.x && nextInside.y) chunks |= 4u;
  if (all(equal(hi, uvec2(SG_CHUNK_SIZE))) && all(nextInside)) chunks |= 8u;
  uint64_t ownBits = sgBoxBits(min(lo, last), min(hi, last));
  uint64_t rightBits = sgBoxBits(uvec2(0, lo.y), uvec2(0, min(hi.y, last.y)));
  uint64_t belowBits = sgBoxBits(uvec2(lo.x, 0), uvec2(min(hi.x, last.x), 0));
  while (chunks != 0u) {
    uint which = uint(findLSB(chunks));
    chunks &= chunks - 1u;
    uvec2 step = uvec2(which & 1u, which >> 1u);
    uint64_t bits = which == 0u ? ownBits : which == 1u ? rightBits : which == 2u ? belowBits : uint64_t(1);
    uvec2 origin = chunkOrigin + step * SG_CHUNK_SIZE;
    sgMarkShadels(sgMarkStorageBase(level, origin) + sgShadelAddress(origin, params.entriesPerSideLog2).chunkIndex, bits);
  }
}
#endif  // SG_MARK_OWN_CHUNK_ONLY
#endif  // SG_SHADEL_MASKS

void markLevel(uint index) {
  uvec4 r = texelFetch(levelRectTexels, int(inLevels.w + index));
  SgMarkLevel level = sgMarkLevel(inLevels, index, SgLevelRect(r.xy, r.z, r.w));
  SgLevelRect rect = level.rect;
  SgBilinearTaps taps = sgBilinearTaps(inShadingUv, rect.size);
  uvec2 tile = sgFootprintTileShadel(rect, taps);
#ifndef SG_MARK_OWN_CHUNK_ONLY
  // Read first: most pixels find their chunk already marked, and a read is
  // much cheaper than an atomic. (With SG_MARK_OWN_CHUNK_ONLY the occupancy
  // bit follows from the chunk's mask: shadel_mark_neighbours.comp.)
  sgMarkChunk(sgShadelAddress(tile, params.entriesPerSideLog2));
#endif
#ifdef SG_SHADEL_MASKS
  markFootprint(level, taps, tile);
#endif
}

const bool kMarkCoarse = SG_FILTER == SG_FILTER_TRILINEAR;
#endif

void main() {
#ifdef SG_MARK_BASELINE
  SgShadelInstance instance = shadelInstances[object.objectId];
  uvec2 levels = uvec2(instance.level0Size, instance.levelCount);
#else
  uvec2 levels = inLevels.xy;
#endif
  float size0 = float(levels.x);
  SgLevelSelection sel =
      sgSelectFilterLevel(SG_FILTER, dFdx(inShadingUv) * size0, dFdy(inShadingUv) * size0, params.bias, levels.y);
#ifdef SG_ALPHA_TEST
#ifdef SG_MARK_REQUESTS
  if (sgMaskedOut(inUv0, inUv1, inColorAlpha)) discard;  // no request: the clear stays
#else
  if (sgMaskedOut(inUv0, inUv1, inColorAlpha)) return;  // after the derivatives: uniform control flow for them
#endif
#endif
  markLevel(sel.fine);
  if (kMarkCoarse && sel.coarse != sel.fine) markLevel(sel.coarse);
}
