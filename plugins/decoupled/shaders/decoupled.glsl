// What every decoupled-shading pass shares: the descriptor bindings of set 0
// (each pass's pipeline layout lists the ones it uses), the per-object table
// and the shade counters. Mirrors plugins/decoupled/decoupled_tables.hpp.
#ifndef SG_DECOUPLED_GLSL
#define SG_DECOUPLED_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_scalar_block_layout : require

#include <framework/shadel/shaders/shadel_level.glsl>

const uint SG_STORAGE_COUNTERS = 16u;
const uint SG_MAX_LEVELS = 16u;
const uint SG_MAX_PERSISTENT_LAYERS = 8u;

// sg::plugins::DecoupledObject: one decoupled instance (all its primitives share one material).
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
};

// sg::plugins::ShadeCounters.
struct SgShadeCounters {
  uint allocated[SG_STORAGE_COUNTERS];  // chunks taken from each storage partition
  uint chunksMarked;
  uint chunksAllocated;
  uint overflowChunks;
  uint compositeMisses;
  uint coveredPixels;                   // fragments composite wrote
  uint levelChunks[SG_MAX_LEVELS];      // marked chunks per detail level
  uint supportChunks;                   // chunks support-expand added around the marked ones
  uint layerReused[SG_MAX_PERSISTENT_LAYERS];    // per persistent layer: shadels served from last frame
  uint layerComputed[SG_MAX_PERSISTENT_LAYERS];  // and shadels computed
};

layout(set = 0, binding = 1, std140) uniform DecoupledParams {
  float bias;                 // global fractional level bias (the adjuster's)
  uint entriesPerSideLog2;    // virtual sheet
  uint storageWidthChunks;    // layer image width in chunks
  uint chunksPerCounter;      // storage partition size
  uint ownedEntryCount;
  uint objectCount;
  uint workCapacity;          // work items the work buffer holds
  uint storageCounters;       // partitions in use (<= SG_STORAGE_COUNTERS)
} params;

layout(set = 0, binding = 2, std430) readonly buffer Objects { SgDecoupledObject objects[]; };
layout(set = 0, binding = 3, std430) readonly buffer ShadelInstances { SgShadelInstance shadelInstances[]; };
layout(set = 0, binding = 4, std430) readonly buffer LevelRects { SgLevelRect levelRects[]; };
layout(set = 0, binding = 5, std430) buffer Remap { SgRemapEntry remap[]; };
layout(set = 0, binding = 6, std430) readonly buffer OwnedEntries { SgOwnedEntry ownedEntries[]; };
layout(set = 0, binding = 7, std430) buffer Counters { SgShadeCounters counters; };

SgLevelRect sgLevelRect(uint object, uint level) { return levelRects[shadelInstances[object].firstLevelRect + level]; }

#endif
