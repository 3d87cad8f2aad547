#version 460
#ifdef SG_COUNT_PER_SUBGROUP
#extension GL_KHR_shader_subgroup_ballot : require
#endif
// Filters the shaded samples: the same level selection as shadel-mark
// (sgSelectFilterLevel: the nearest level for point and bilinear, fine and
// coarse for trilinear), then the filter's taps from one chunk tile per
// level. A lookup that finds no stored shadel is counted (composite misses:
// must be zero, the watertightness guarantee).
#include <framework/render/shaders/object.glsl>
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/render/shaders/debug_color.glsl>

layout(early_fragment_tests) in;
layout(set = 0, binding = kBindLayerImage) uniform sampler2D layerImage;  // texelFetch only
layout(location = 0) in vec2 inShadingUv;
layout(location = 0) out vec4 outColor;

#ifdef SG_ALPHA_TEST
// Alpha-mask objects: the pixels their alpha test cuts away (the z-prepass
// gave them no depth there) neither mark nor composite.
#include <passes/alpha-mask/alpha_test.glsl>
layout(location = 1) in vec2 inUv0;
layout(location = 2) in vec2 inUv1;
layout(location = 3) in float inColorAlpha;
#endif

// SG_FILTER (shadel_level.glsl's SG_FILTER_*): the filter, the same define
// shadel-mark is compiled with, so composite reads only what mark marked.
#ifndef SG_FILTER
#error "SG_FILTER: the composite filter (passes::filterDefine)"
#endif
const uint kFilter = SG_FILTER;

layout(location = 4) flat in uvec3 inLevels;  // level0Size, levelCount, firstLevelRect

// The tables read through texel views (a gather on lavapipe, where a
// storage-buffer read is a loop over the lanes).
layout(set = 0, binding = kBindLevelRectTexels) uniform usamplerBuffer levelRectTexels;  // RGBA32UI: SgLevelRect
layout(set = 0, binding = kBindRemapTexels) uniform usamplerBuffer remapTexels;          // RGBA32UI: SgRemapEntry
layout(set = 0, binding = kBindChunkSlotTexels) uniform usamplerBuffer chunkSlotTexels;  // R32UI

// sgStoredChunk, its reads through the texel views.
uint storedChunk(SgShadelAddress a) {
  uvec4 t = texelFetch(remapTexels, int(a.entryIndex));
  SgRemapEntry entry = SgRemapEntry(t.x, t.y, packUint2x32(t.zw));
  if (!sgChunkHasSlot(entry, a.chunkIndex)) return SG_INVALID_CHUNK;
  return sgSlotChunk(texelFetch(chunkSlotTexels, int(entry.storageBase + a.chunkIndex)).x);
}

// The level's footprint is in one chunk tile of shade storage (the chunk and
// its one-shadel gutter): the tile of the top-left tap, the chunk shadel-mark
// marked. One remap lookup per level.
vec4 filterLevel(uint level) {
  uvec4 r = texelFetch(levelRectTexels, int(inLevels.z + level));
  SgLevelRect rect = SgLevelRect(r.xy, r.z, r.w);
  SgBilinearTaps taps = sgBilinearTaps(inShadingUv, rect.size);
  uvec2 shadel = sgFootprintTileShadel(rect, taps);
  SgShadelAddress a = sgShadelAddress(shadel, params.entriesPerSideLog2);
  uint physical = storedChunk(a);
  if (physical == SG_INVALID_CHUNK) {
    atomicAdd(counters.compositeMisses, 1u);
    return vec4(1.0, 0.0, 1.0, 1.0);  // magenta: visible if it ever happens
  }
  ivec2 t = ivec2(sgStoredTexel(physical, shadel & (SG_CHUNK_SIZE - 1u), params.storageWidthChunks));
  if (kFilter == SG_FILTER_POINT) return texelFetch(layerImage, t + ivec2(greaterThanEqual(taps.weight, vec2(0.5))), 0);
  vec4 c00 = texelFetch(layerImage, t, 0), c10 = texelFetch(layerImage, t + ivec2(1, 0), 0);
  vec4 c01 = texelFetch(layerImage, t + ivec2(0, 1), 0), c11 = texelFetch(layerImage, t + ivec2(1, 1), 0);
  return mix(mix(c00, c10, taps.weight.x), mix(c01, c11, taps.weight.x), taps.weight.y);
}

// Covered pixels (a statistic). SG_COUNT_PER_SUBGROUP (compositePipeline:
// lavapipe) adds them per subgroup: there every atomic is a loop over the
// lanes with a locked add per lane, on a cache line both rasterizer threads
// write (a third of composite's time on DamagedHelmet), and uncovered
// (helper) lanes stay out of subgroup operations. Elsewhere helper lanes may
// take part: each pixel adds itself (a helper's atomic is dropped).
void countCoveredPixel() {
#ifdef SG_COUNT_PER_SUBGROUP
  uint covered = subgroupBallotBitCount(subgroupBallot(true));
  if (subgroupElect()) atomicAdd(counters.coveredPixels, covered);
#else
  atomicAdd(counters.coveredPixels, 1u);
#endif
}

void main() {
  float size0 = float(inLevels.x);
  SgLevelSelection sel =
      sgSelectFilterLevel(SG_FILTER, dFdx(inShadingUv) * size0, dFdy(inShadingUv) * size0, params.bias, inLevels.y);
#ifdef SG_ALPHA_TEST
  if (sgMaskedOut(inUv0, inUv1, inColorAlpha)) discard;  // after the derivatives: uniform control flow for them
#endif
  countCoveredPixel();
#ifdef SG_VIEW_LEVEL
  // --view level: the detail level the pixel reads (fractional: fine + blend), shaded lightly.
  vec4 shaded = filterLevel(sel.fine);
  float level = float(sel.fine) + sel.blend;
  outColor = vec4(sgLevelColor(level) * (0.55 + 0.45 * clamp(dot(shaded.rgb, vec3(0.3, 0.5, 0.2)), 0.0, 1.0)), 1.0);
#else
  vec4 color = filterLevel(sel.fine);
  if (kFilter == SG_FILTER_TRILINEAR && sel.coarse != sel.fine) color = mix(color, filterLevel(sel.coarse), sel.blend);
  outColor = vec4(color.rgb, 1.0);
#endif
}
