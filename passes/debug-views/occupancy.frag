#version 460
// --view occupancy: the used part of the virtual shadel sheet, one pixel per
// chunk. Marked chunks in their level's colour, allocated-but-unmarked chunks
// dark grey, chunks that got no storage (overflow) white, the rest black.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/render/shaders/debug_color.glsl>

layout(push_constant, scalar) uniform Push { SgOccupancyPush push; };
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
  uvec2 chunk = push.originChunks + uvec2(inUv * vec2(push.sizeChunks));
  uvec2 shadel = chunk * SG_CHUNK_SIZE;
  SgShadelAddress a = sgShadelAddress(shadel, params.entriesPerSideLog2);
  SgRemapEntry entry = remap[a.entryIndex];
  outColor = vec4(0.0, 0.0, 0.0, 1.0);
  if (entry.objectInstanceId == SG_NO_INSTANCE || entry.objectInstanceId >= params.objectCount) return;
  SgShadelInstance instance = shadelInstances[entry.objectInstanceId];
  for (uint level = 0u; level < instance.levelCount; ++level) {
    SgLevelRect rect = levelRects[instance.firstLevelRect + level];
    if (any(lessThan(shadel, rect.origin)) || any(greaterThanEqual(shadel, rect.origin + rect.allocatedSize))) continue;
    if (!sgIsChunkMarked(entry.occupancy, a.chunkIndex)) outColor = vec4(0.12, 0.12, 0.12, 1.0);
    else if (sgStoredChunk(entry, a.chunkIndex) == SG_INVALID_CHUNK) outColor = vec4(1.0);
    else outColor = vec4(sgLevelColor(float(level)), 1.0);
    return;
  }
}
