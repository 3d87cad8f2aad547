// What the decoupled (compute) variant of every material layer starts from:
// the shadel this invocation shades (from the object's work list, one 8x8
// chunk per workgroup), its surface point, and reads of earlier layers and of
// last frame at shadels of the same level. The framework's generated variant
// includes this, declares the layer images, then the author's source.
//
// For each shadel: its UV at its level -> the triangle from the ID map ->
// barycentrics clamped to [-eps, 1+eps] (a shadel just outside its triangle
// extrapolates it, as the ID map's conservative texels intend) -> vertex
// attributes and their derivatives per shadel step, interpolated as a
// fragment shader would.
#ifndef SG_SHADEL_CONTEXT_GLSL
#define SG_SHADEL_CONTEXT_GLSL

#extension GL_EXT_scalar_block_layout : require
#extension GL_KHR_shader_subgroup_ballot : require
#include <framework/render/shaders/frame.glsl>
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/work.glsl>
#include <framework/plugin/shaders/material.glsl>
#include <passes/layer-shade/marked_shadels.glsl>

// A workgroup shades one 8x8 chunk with 64 / SG_CHUNK_ROWS_PER_INVOCATION
// invocations, each shading that many of its shadels (the loop in the
// generated main): a layer that keeps values shades the rows of its column,
// any other the chunk's marked shadels packed into full lanes
// (marked_shadels.glsl). The generator sizes the workgroup to one subgroup
// (passes::chunkRowsPerInvocation): the chunk setup (sgChunkSetup, its
// single-lane reads) then runs once per chunk. On lavapipe (8 lanes) that is
// 8 rows per invocation; 8 subgroups each repeating the setup cost
// debug-triangle-id about half its layer-shade time. On a GPU (32-64 lanes)
// 8 invocations would waste most of a wave.
#ifndef SG_CHUNK_ROWS_PER_INVOCATION
#error "SG_CHUNK_ROWS_PER_INVOCATION: rows of its chunk column an invocation shades (passes::chunkRowsPerInvocation)"
#endif
layout(local_size_x = 8, local_size_y = 8u / SG_CHUNK_ROWS_PER_INVOCATION) in;

struct SgVertex {  // render::GpuVertex
  vec3 position;
  vec3 normal;
  vec4 tangent;
  vec4 uv01;
  vec4 color;
};
// The ID maps, vertices and indices are uniform texel buffers: on CPU devices
// (lavapipe) a texelFetch is one gather across the lanes, where a storage-buffer
// read at per-lane addresses is a loop over the lanes with a branch and a
// bounds check each (and these reads were half of a simple layer's time).
layout(set = 0, binding = kBindIdMaps) uniform usamplerBuffer sgIdMaps;       // R32UI
layout(set = 0, binding = kBindVertices) uniform samplerBuffer sgVertexTexels;  // RG32F, 9 per render::GpuVertex
layout(set = 0, binding = kBindIndices) uniform usamplerBuffer sgIndices;     // R32UI

// Vertex i as render::GpuVertex lays it out in nine RG32F texels; the
// compiler drops the fetches of what the layer does not use.
SgVertex sgVertex(uint i) {
  int t = int(i) * 9;
  vec2 t0 = texelFetch(sgVertexTexels, t).xy, t1 = texelFetch(sgVertexTexels, t + 1).xy,
       t2 = texelFetch(sgVertexTexels, t + 2).xy, t3 = texelFetch(sgVertexTexels, t + 3).xy,
       t4 = texelFetch(sgVertexTexels, t + 4).xy, t5 = texelFetch(sgVertexTexels, t + 5).xy,
       t6 = texelFetch(sgVertexTexels, t + 6).xy, t7 = texelFetch(sgVertexTexels, t + 7).xy,
       t8 = texelFetch(sgVertexTexels, t + 8).xy;
  return SgVertex(vec3(t0, t1.x), vec3(t1.y, t2), vec4(t3, t4), vec4(t5, t6), vec4(t7, t8));
}
layout(push_constant, scalar) uniform Push { SgLayerShadePush sgPush; };

const uint SG_NO_TRIANGLE = 0xFFFFFFFFu;
const float kBarycentricEpsilon = 0.05;

// The shadel being shaded.
struct SgShadelContext {
  ivec2 target;        // its texel in the layer images
  uvec2 shadel;        // virtual sheet coordinates
  uvec2 local;         // inside its level rectangle
  SgLevelRect rect;
  uint level;
  uint triangle;       // SG_NO_TRIANGLE: nothing to shade (outside the chart or past the level's edge)
  uint levelOffset;    // of its level in the object's ID map
  uint idMapLevel;     // the first texel of its level in the ID-map buffer
};
SgShadelContext sgShadel;

// The detail level of the shadel (0 = finest).
float sgDetailLevel() { return float(sgShadel.level); }
uint sgTriangleId() { return sgShadel.triangle; }

uint sgTriangleAt(uvec2 local) {
  return texelFetch(sgIdMaps, int(sgShadel.idMapLevel + local.y * sgShadel.rect.size + local.x)).x;
}

vec3 sgBarycentrics(vec2 p, vec2 a, vec2 b, vec2 c) {
  vec2 v0 = b - a, v1 = c - a, v2 = p - a;
  float d = v0.x * v1.y - v1.x * v0.y;
  float v = (v2.x * v1.y - v1.x * v2.y) / d;
  float w = (v0.x * v2.y - v2.x * v0.y) / d;
  return vec3(1.0 - v - w, v, w);
}

// This workgroup's place in the object's work list (one chunk each): dispatches
// run in rows of up to 65,535 groups (work_offsets.comp), so the last row may
// reach past the list's end; those groups do nothing (sgWorkGroupInList).
uint sgWorkGroupIndex() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }
bool sgWorkGroupInList() {
  uint lead = subgroupBroadcastFirst(gl_SubgroupInvocationID), chunks = 0u;
  if (gl_SubgroupInvocationID == lead) chunks = work[sgObjectChunksSlot(sgPush.objectIndex)];  // one read (sgChunkSetup)
  return sgWorkGroupIndex() < subgroupBroadcast(chunks, lead);
}

// The shadels of a chunk that composite reads (shadel-mark's mask, bit =
// texel index), or all 64: without masks this frame, and for an object whose
// material reads a neighbourhood (support-expand grows whole chunks; their
// neighbours' shadels must exist). Read in sgChunkSetup.
layout(set = 0, binding = kBindShadelMasks, std430) readonly buffer ShadelMasks { uint64_t sgShadelMasks[]; };

// What every shadel of a workgroup shares: its chunk's work item and shadel
// mask, the object's record and the level's rectangle. One lane of each subgroup reads
// them and broadcasts: on CPU devices (lavapipe) every lane's buffer read is a
// scalar load and a bounds check of its own, however uniform the address, and
// these reads cost as much as the shadel's own (ID map, indices, vertices).
struct SgChunkSetup {
  uint entryIndex, chunkIndex, level, physical;
  uvec2 storageOrigin;  // of the chunk's tile in the layer images
  uvec2 shadelMask;     // the shadels composite reads (bit = texel index), as two halves
  SgLevelRect rect;
  uint idMapLevel;    // the first texel of the level in the ID-map buffer
  uint levelOffset;   // of the level in the object's ID map
  uint firstIndex;
  int vertexOffset;
  uint shadingUvSet;
  vec2 tileOffset;
  mat4 world;
};

SgChunkSetup sgReadChunkSetup() {
  SgChunkSetup c;
  SgDecoupledObject o = objects[sgPush.objectIndex];
  uint item = sgWorkItemSlot(work[sgObjectOffsetSlot(sgPush.objectIndex)] + sgWorkGroupIndex());
  c.entryIndex = work[item];
  c.chunkIndex = work[item + 1u];
  c.level = work[item + 2u];
  c.physical = work[item + 3u];
  c.storageOrigin = sgStoredTexel(c.physical, uvec2(0u), params.storageWidthChunks);
  c.shadelMask = uvec2(0xFFFFFFFFu);
  if (sgPush.shadelMasks != 0u && o.supportChunks == 0u)
    c.shadelMask = unpackUint2x32(sgShadelMasks[remap[c.entryIndex].storageBase + c.chunkIndex]);
  SgShadelInstance instance = shadelInstances[sgPush.objectIndex];
  c.rect = levelRects[sgLevelRectIndex(instance, c.level)];
  c.levelOffset = 0u;
  for (uint l = 0u; l < c.level; ++l) c.levelOffset += (instance.level0Size >> l) * (instance.level0Size >> l);
  c.idMapLevel = o.idMapOffset + c.levelOffset;
  c.firstIndex = o.firstIndex;
  c.vertexOffset = o.vertexOffset;
  c.shadingUvSet = o.shadingUvSet;
  c.tileOffset = o.tileOffset;
  c.world = o.world;
  return c;
}

// Every lane gets the first active lane's setup. subgroupBroadcast from an
// index found once: lavapipe finds the first active lane by a loop over the
// lanes for every subgroupBroadcastFirst, and reads a given lane directly.
SgChunkSetup sgChunkSetup() {
  uint lead = subgroupBroadcastFirst(gl_SubgroupInvocationID);
  SgChunkSetup c;
  if (gl_SubgroupInvocationID == lead) c = sgReadChunkSetup();
  c.entryIndex = subgroupBroadcast(c.entryIndex, lead);
  c.chunkIndex = subgroupBroadcast(c.chunkIndex, lead);
  c.level = subgroupBroadcast(c.level, lead);
  c.physical = subgroupBroadcast(c.physical, lead);
  c.storageOrigin = subgroupBroadcast(c.storageOrigin, lead);
  c.shadelMask = subgroupBroadcast(c.shadelMask, lead);
  c.rect.origin = subgroupBroadcast(c.rect.origin, lead);
  c.rect.size = subgroupBroadcast(c.rect.size, lead);
  c.rect.allocatedSize = subgroupBroadcast(c.rect.allocatedSize, lead);
  c.idMapLevel = subgroupBroadcast(c.idMapLevel, lead);
  c.levelOffset = subgroupBroadcast(c.levelOffset, lead);
  c.firstIndex = subgroupBroadcast(c.firstIndex, lead);
  c.vertexOffset = subgroupBroadcast(c.vertexOffset, lead);
  c.shadingUvSet = subgroupBroadcast(c.shadingUvSet, lead);
  c.tileOffset = subgroupBroadcast(c.tileOffset, lead);
  for (int k = 0; k < 4; ++k) c.world[k] = subgroupBroadcast(c.world[k], lead);
  return c;
}

vec2 sgShadingUv(SgVertex v, SgChunkSetup c) { return (c.shadingUvSet == 1u ? v.uv01.zw : v.uv01.xy) - c.tileOffset; }

// The texel indices (8x8 row-major) of the chunk this invocation shades: row
// `row` of its column.
uint sgFirstShadelRow() { return gl_LocalInvocationID.y * SG_CHUNK_ROWS_PER_INVOCATION; }
uint sgChunkTexel(uint row) { return row * SG_CHUNK_SIZE + gl_LocalInvocationID.x; }

// Marked shadel slot -> texel: the shadels composite reads, in full lanes.
const uint SG_LAYER_SHADE_INVOCATIONS = 64u / SG_CHUNK_ROWS_PER_INVOCATION;

// Finds shadel texelIndex of the chunk (sgShadel) and, if it lies on the
// object, its surface point. False: write nothing meaningful (the layer gets vec4(0)).
bool sgBeginShadel(SgChunkSetup c, uint texelIndex, out Surface s) {
  sgShadel.target = ivec2(c.storageOrigin + sgTexelInChunk(texelIndex));
  sgShadel.shadel = sgVirtualShadel(SgShadelAddress(c.entryIndex, c.chunkIndex, texelIndex), params.entriesPerSideLog2);
  sgShadel.rect = c.rect;
  sgShadel.level = c.level;
  sgShadel.local = sgShadel.shadel - sgShadel.rect.origin;
  sgShadel.triangle = SG_NO_TRIANGLE;
  sgShadel.levelOffset = c.levelOffset;
  sgShadel.idMapLevel = c.idMapLevel;
  s = Surface(vec3(0.0), vec3(0.0, 0.0, 1.0), vec4(1.0, 0.0, 0.0, 1.0), vec2(0.0), vec2(0.0), vec4(0.0), vec2(0.0),
              vec2(0.0), vec2(0.0), vec2(0.0), vec3(0.0), vec3(0.0));
  // Chunks of levels smaller than a chunk, and texels past the level's edge.
  if (sgShadel.local.x >= sgShadel.rect.size || sgShadel.local.y >= sgShadel.rect.size) return false;
  sgShadel.triangle = sgTriangleAt(sgShadel.local);
  if (sgShadel.triangle == SG_NO_TRIANGLE) return false;

  int first = int(c.firstIndex + 3u * sgShadel.triangle);
  uvec3 i = uvec3(texelFetch(sgIndices, first).x, texelFetch(sgIndices, first + 1).x, texelFetch(sgIndices, first + 2).x) +
            uint(c.vertexOffset);
  SgVertex v0 = sgVertex(i.x), v1 = sgVertex(i.y), v2 = sgVertex(i.z);
  vec2 s0 = sgShadingUv(v0, c), s1 = sgShadingUv(v1, c), s2 = sgShadingUv(v2, c);

  float step = 1.0 / float(sgShadel.rect.size);
  vec2 uv = (vec2(sgShadel.local) + 0.5) * step;
  vec3 b = clamp(sgBarycentrics(uv, s0, s1, s2), -kBarycentricEpsilon, 1.0 + kBarycentricEpsilon);
  b /= b.x + b.y + b.z;
  // Barycentrics are affine in UV: their change per shadel step is exact and
  // the same everywhere in the triangle.
  vec3 bDx = sgBarycentrics(uv + vec2(step, 0.0), s0, s1, s2) - sgBarycentrics(uv, s0, s1, s2);
  vec3 bDy = sgBarycentrics(uv + vec2(0.0, step), s0, s1, s2) - sgBarycentrics(uv, s0, s1, s2);

  mat3 normalMatrix = transpose(inverse(mat3(c.world)));
  s.position = (c.world * vec4(v0.position * b.x + v1.position * b.y + v2.position * b.z, 1.0)).xyz;
  s.normal = normalize(normalMatrix * (v0.normal * b.x + v1.normal * b.y + v2.normal * b.z));
  vec4 t = v0.tangent * b.x + v1.tangent * b.y + v2.tangent * b.z;
  // A mirroring world matrix flips cross(normal, tangent): flip the handedness with it (as forward.vert).
  s.tangent = vec4(mat3(c.world) * t.xyz, determinant(mat3(c.world)) < 0.0 ? -v0.tangent.w : v0.tangent.w);
  s.uv0 = v0.uv01.xy * b.x + v1.uv01.xy * b.y + v2.uv01.xy * b.z;
  s.uv1 = v0.uv01.zw * b.x + v1.uv01.zw * b.y + v2.uv01.zw * b.z;
  s.color = v0.color * b.x + v1.color * b.y + v2.color * b.z;
  s.uv0Dx = v0.uv01.xy * bDx.x + v1.uv01.xy * bDx.y + v2.uv01.xy * bDx.z;
  s.uv0Dy = v0.uv01.xy * bDy.x + v1.uv01.xy * bDy.y + v2.uv01.xy * bDy.z;
  s.uv1Dx = v0.uv01.zw * bDx.x + v1.uv01.zw * bDx.y + v2.uv01.zw * bDx.z;
  s.uv1Dy = v0.uv01.zw * bDy.x + v1.uv01.zw * bDy.y + v2.uv01.zw * bDy.z;
  s.positionDx = mat3(c.world) * (v0.position * bDx.x + v1.position * bDx.y + v2.position * bDx.z);
  s.positionDy = mat3(c.world) * (v0.position * bDy.x + v1.position * bDy.y + v2.position * bDy.z);
  // Double-sided surfaces seen from behind: shade the side facing the camera.
  if (material.flags.y != 0u && dot(s.normal, frame.cameraPosition.xyz - s.position) < 0.0) s.normal = -s.normal;
  return true;
}

// An earlier layer's value `offset` shadels away at the same level. Past the
// level's edge, off the chart, or in a chunk nobody shaded (only past the
// support a layer declared), it reads the shadel itself.
vec4 sgFetchLayer(sampler2D image, ivec2 offset) {
  ivec2 local = clamp(ivec2(sgShadel.local) + offset, ivec2(0), ivec2(sgShadel.rect.size) - 1);
  if (offset != ivec2(0) && sgTriangleAt(uvec2(local)) == SG_NO_TRIANGLE) local = ivec2(sgShadel.local);
  SgShadelAddress a = sgShadelAddress(sgShadel.rect.origin + uvec2(local), params.entriesPerSideLog2);
  uint physical = sgStoredChunk(remap[a.entryIndex], a.chunkIndex);
  if (physical == SG_INVALID_CHUNK) return texelFetch(image, sgShadel.target, 0);
  return texelFetch(image, ivec2(sgStorageTexel(physical, a.texelIndex, params.storageWidthChunks)), 0);
}

#endif
