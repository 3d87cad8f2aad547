#version 460
// Marks the chunks of every shadel composite will read for this pixel: the
// trilinear footprint, 4 shadels at the fine level and 4 at the coarse one.
// Early depth test: hidden surfaces mark nothing. No colour output.
#include <framework/render/shaders/object.glsl>
#include <framework/shadel/shaders/decoupled.glsl>

layout(early_fragment_tests) in;
layout(location = 0) in vec2 inShadingUv;

void markShadel(uvec2 shadel) {
  SgShadelAddress a = sgShadelAddress(shadel, params.entriesPerSideLog2);
  uint64_t bit = sgChunkBit(a.chunkIndex);
  // Read first: most pixels find their chunk already marked, and a plain read
  // is much cheaper than an atomic.
  if ((remap[a.entryIndex].occupancy & bit) == uint64_t(0)) atomicOr(remap[a.entryIndex].occupancy, bit);
}

void markLevel(uint level) {
  SgLevelRect rect = sgLevelRect(object.objectId, level);
  SgBilinearTaps taps = sgBilinearTaps(inShadingUv, rect.size);
  for (uint i = 0u; i < 4u; ++i) markShadel(sgFootprintShadel(rect, taps, i));
}

void main() {
  SgShadelInstance instance = shadelInstances[object.objectId];
  float size0 = float(instance.level0Size);
  SgLevelSelection sel =
      sgSelectDetailLevel(dFdx(inShadingUv) * size0, dFdy(inShadingUv) * size0, params.bias, instance.levelCount);
  markLevel(sel.fine);
  if (sel.coarse != sel.fine) markLevel(sel.coarse);
}
