#pragma once
// Host mirrors of the GPU records in plugins/decoupled/shaders/decoupled.glsl.
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace sg::plugins {

inline constexpr uint32_t kStorageCounters = 16;  // SG_STORAGE_COUNTERS
inline constexpr uint32_t kMaxLevels = 16;        // SG_MAX_LEVELS

// SgDecoupledObject (std430).
struct DecoupledObject {
  glm::mat4 world;
  uint32_t firstIndex;
  int32_t vertexOffset;
  uint32_t triangleCount;
  uint32_t material;
  uint32_t idMapOffset;
  uint32_t shadingUvSet;
  glm::vec2 tileOffset;
  uint32_t supportChunks;  // support-expand grows its marked chunks by this many (0: no neighbourhood layer)
  uint32_t pad[3];
};
static_assert(sizeof(DecoupledObject) == 112);

inline constexpr uint32_t kMaxPersistentLayers = 8;  // SG_MAX_PERSISTENT_LAYERS

// SgShadeCounters (std430).
struct ShadeCounters {
  uint32_t allocated[kStorageCounters];
  uint32_t chunksMarked;
  uint32_t chunksAllocated;
  uint32_t overflowChunks;
  uint32_t compositeMisses;
  uint32_t coveredPixels;
  uint32_t levelChunks[kMaxLevels];
  uint32_t supportChunks;  // chunks support-expand added around the marked ones
  uint32_t layerReused[kMaxPersistentLayers];    // per persistent layer: shadels served from last frame
  uint32_t layerComputed[kMaxPersistentLayers];  // and shadels computed
};

// DecoupledParams (std140).
struct DecoupledParams {
  float bias;
  uint32_t entriesPerSideLog2;
  uint32_t storageWidthChunks;
  uint32_t chunksPerCounter;
  uint32_t ownedEntryCount;
  uint32_t objectCount;
  uint32_t workCapacity;
  uint32_t storageCounters;
  uint32_t pad[4];
};
static_assert(sizeof(DecoupledParams) == 48);

// The work buffer (work.glsl): 3 counters per object, then 4 uints per item.
constexpr uint64_t workBufferBytes(uint32_t objects, uint32_t items) { return 4ull * (3ull * objects + 4ull * items); }

}  // namespace sg::plugins
