#version 460
// Marks the chunks composite will read for this pixel: at each level the
// composite filter (SG_FILTER, the same define composite is compiled with)
// reads (sgSelectFilterLevel: the nearest for point and bilinear, fine and
// coarse for trilinear), the chunk of the footprint's top-left tap, whose
// tile in shade storage (the chunk and a one-shadel gutter) holds the whole
// footprint. One remap read per level, an atomic only when the bit is missing.
// With SG_SHADEL_MASKS it also marks which shadels of the chunk the footprint
// reads (layer-shade shades only those): one more atomicOr per level, and
// one per neighbour chunk whose first row or column fills the tile's gutter.
// Early depth test: hidden surfaces mark nothing. No colour output.
#include <framework/render/shaders/object.glsl>
#include <framework/shadel/shaders/decoupled.glsl>

#ifndef SG_FILTER
#error "SG_FILTER: the composite filter (passes::filterDefine)"
#endif

layout(early_fragment_tests) in;
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
#ifdef SG_SHADEL_MASKS
layout(set = 0, binding = kBindShadelMasks, std430) buffer ShadelMasks { uint64_t shadelMasks[]; };

// Sets `bits` in the shadel mask of chunk `chunk` of a remap entry whose
// chunk slots start at `storageBase` (shadel-clear sets it for every owned
// entry). Read first, as for the chunk bit.
void markShadels(uint storageBase, uint chunk, uint64_t bits) {
  uint slot = storageBase + chunk;
  if ((shadelMasks[slot] & bits) != bits) atomicOr(shadelMasks[slot], bits);
}

// The neighbour chunk `step` chunks from the tile's (right, below or
// diagonal) gives its first column / row to the tile's gutter when it is
// inside the level; else the gutter repeats the tile's own edge shadels,
// which the tile's own mask holds (clamped box below).
void markNeighbour(SgLevelRect rect, uvec2 chunkOrigin, uvec2 step, uint64_t bits) {
  uvec2 origin = chunkOrigin + step * SG_CHUNK_SIZE;
  if (any(greaterThanEqual(origin - rect.origin, uvec2(rect.size)))) return;
  SgShadelAddress n = sgShadelAddress(origin, params.entriesPerSideLog2);
  markShadels(remap[n.entryIndex].storageBase, n.chunkIndex, bits);
}

// The shadels of a chunk in the box [lo, hi] (inclusive, inside [0,8)²).
uint64_t sgBoxBits(uvec2 lo, uvec2 hi) {
  uint row = ((2u << (hi.x - lo.x)) - 1u) << lo.x;
  uint64_t bits = uint64_t(0);
  for (uint y = lo.y; y <= hi.y; ++y) bits |= uint64_t(row) << (SG_CHUNK_SIZE * y);
  return bits;
}

// What composite reads of the tile: the footprint's taps at (tile & 7) +
// [lo, hi] in the 9x9 tile, whatever their weight (a weight-0 tap is still
// fetched). Point: the nearest tap only; bilinear, trilinear: the 2x2.
void markFootprint(SgLevelRect rect, SgBilinearTaps taps, uvec2 tile, uint storageBase, uint chunk) {
  uvec2 inChunk = tile & (SG_CHUNK_SIZE - 1u);
  uvec2 lo = inChunk, hi = inChunk + 1u;
  if (SG_FILTER == SG_FILTER_POINT) {
    lo += uvec2(greaterThanEqual(taps.weight, vec2(0.5)));
    hi = lo;
  }
  uvec2 last = uvec2(SG_CHUNK_SIZE - 1u);
  markShadels(storageBase, chunk, sgBoxBits(min(lo, last), min(hi, last)));
  uvec2 chunkOrigin = tile - inChunk;
  if (hi.x == SG_CHUNK_SIZE && lo.y <= last.y)
    markNeighbour(rect, chunkOrigin, uvec2(1, 0), sgBoxBits(uvec2(0, lo.y), uvec2(0, min(hi.y, last.y))));
  if (hi.y == SG_CHUNK_SIZE && lo.x <= last.x)
    markNeighbour(rect, chunkOrigin, uvec2(0, 1), sgBoxBits(uvec2(lo.x, 0), uvec2(min(hi.x, last.x), 0)));
  if (all(equal(hi, uvec2(SG_CHUNK_SIZE)))) markNeighbour(rect, chunkOrigin, uvec2(1, 1), uint64_t(1));
}
#endif

void markLevel(uint level) {
  SgLevelRect rect = sgLevelRect(object.objectId, level);
  SgBilinearTaps taps = sgBilinearTaps(inShadingUv, rect.size);
  uvec2 tile = sgFootprintTileShadel(rect, taps);
  SgShadelAddress a = sgShadelAddress(tile, params.entriesPerSideLog2);
  SgRemapEntry entry = remap[a.entryIndex];
  uint64_t bit = sgChunkBit(a.chunkIndex);
  // Read first: most pixels find their chunk already marked, and a plain
  // read is much cheaper than an atomic.
  if ((entry.occupancy & bit) == uint64_t(0)) atomicOr(remap[a.entryIndex].occupancy, bit);
#ifdef SG_SHADEL_MASKS
  markFootprint(rect, taps, tile, entry.storageBase, a.chunkIndex);
#endif
}

const bool kMarkCoarse = SG_FILTER == SG_FILTER_TRILINEAR;
#endif

void main() {
  SgShadelInstance instance = shadelInstances[object.objectId];
  float size0 = float(instance.level0Size);
  SgLevelSelection sel =
      sgSelectFilterLevel(SG_FILTER, dFdx(inShadingUv) * size0, dFdy(inShadingUv) * size0, params.bias,
                          instance.levelCount);
#ifdef SG_ALPHA_TEST
  if (sgMaskedOut(inUv0, inUv1, inColorAlpha)) return;  // after the derivatives: uniform control flow for them
#endif
  markLevel(sel.fine);
  if (kMarkCoarse && sel.coarse != sel.fine) markLevel(sel.coarse);
}
