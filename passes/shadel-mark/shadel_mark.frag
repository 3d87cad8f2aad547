#version 460
// Marks the chunks of every shadel composite will read for this pixel: the
// footprint of the composite filter (SG_FILTER, the same define composite is
// compiled with) at the levels sgSelectFilterLevel picks for it: point, the
// nearest shadel of the nearest level; bilinear, the 2x2 taps of the nearest
// level; trilinear, the 2x2 of the fine and of the coarse level.
// Each remap entry the footprint touches is read once (the taps of a level
// usually share it) and atomically updated only when a bit is missing.
// Early depth test: hidden surfaces mark nothing. No colour output.
#include <framework/render/shaders/object.glsl>
#include <framework/shadel/shaders/decoupled.glsl>

#ifndef SG_FILTER
#error "SG_FILTER: the composite filter (passes::filterDefine)"
#endif

layout(early_fragment_tests) in;
layout(location = 0) in vec2 inShadingUv;

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
// Marks every chunk of the virtual-shadel rectangle [lo, hi] (hi - lo in {0,1}²).
void markRect(uvec2 lo, uvec2 hi) {
  for (uint side = 0u; side < 4u; ++side) {
    uint entry;
    uint64_t mask;
    if (!sgFootprintEntryMask(lo, hi, side, params.entriesPerSideLog2, entry, mask)) continue;
    // Read first: most pixels find their chunks already marked, and a plain
    // read is much cheaper than an atomic.
    if ((remap[entry].occupancy & mask) != mask) atomicOr(remap[entry].occupancy, mask);
  }
}

void markLevel(uint level) {
  SgLevelRect rect = sgLevelRect(object.objectId, level);
  SgBilinearTaps taps = sgBilinearTaps(inShadingUv, rect.size);
  if (SG_FILTER == SG_FILTER_POINT) {
    uvec2 shadel = rect.origin + sgNearestTap(taps);
    markRect(shadel, shadel);
  } else {
    markRect(rect.origin + taps.lo, rect.origin + taps.hi);
  }
}

const bool kMarkCoarse = SG_FILTER == SG_FILTER_TRILINEAR;
#endif

void main() {
  SgShadelInstance instance = shadelInstances[object.objectId];
  float size0 = float(instance.level0Size);
  SgLevelSelection sel =
      sgSelectFilterLevel(SG_FILTER, dFdx(inShadingUv) * size0, dFdy(inShadingUv) * size0, params.bias,
                          instance.levelCount);
  markLevel(sel.fine);
  if (kMarkCoarse && sel.coarse != sel.fine) markLevel(sel.coarse);
}
