#version 460
// Marks the chunks composite will read for this pixel: at each level the
// composite filter (SG_FILTER, the same define composite is compiled with)
// reads (sgSelectFilterLevel: the nearest for point and bilinear, fine and
// coarse for trilinear), the chunk of the footprint's top-left tap, whose
// tile in shade storage (the chunk and a one-shadel gutter) holds the whole
// footprint. One remap read per level, an atomic only when the bit is missing.
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
void markLevel(uint level) {
  SgLevelRect rect = sgLevelRect(object.objectId, level);
  SgShadelAddress a = sgShadelAddress(sgFootprintTileShadel(rect, sgBilinearTaps(inShadingUv, rect.size)),
                                      params.entriesPerSideLog2);
  uint64_t bit = sgChunkBit(a.chunkIndex);
  // Read first: most pixels find their chunk already marked, and a plain
  // read is much cheaper than an atomic.
  if ((remap[a.entryIndex].occupancy & bit) == uint64_t(0)) atomicOr(remap[a.entryIndex].occupancy, bit);
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
