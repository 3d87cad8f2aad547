#version 460
// Per object: where its work list starts (a prefix sum of the chunk counts)
// and its VkDispatchIndirectCommand, which every layer of its material
// dispatches (they shade the same chunks). Objects with nothing visible get
// {0, 1, 1}; then the same for the reuse list. One invocation: object counts are small. A dispatch dimension
// holds at most 65,535 workgroups (the guaranteed maxComputeWorkGroupCount), so
// a longer list runs as rows of that many; the last row's surplus groups exit.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 1) in;
const uint kMaxGroupsPerRow = 65535u;
layout(set = 0, binding = kBindArgs, std430) writeonly buffer IndirectArgs { uint args[]; };

void main() {
  uint offset = 0u;
  for (uint o = 0u; o < params.objectCount; ++o) {
    uint chunks = work[sgObjectChunksSlot(o)];
    work[sgObjectOffsetSlot(o)] = offset;
    args[3u * o] = min(chunks, kMaxGroupsPerRow);
    args[3u * o + 1u] = max(1u, (chunks + kMaxGroupsPerRow - 1u) / kMaxGroupsPerRow);
    args[3u * o + 2u] = 1u;
    offset += chunks;
  }
  // The reuse list follows the shade lists; shade-reuse dispatches it with the
  // arguments after the objects'.
  uint reused = work[sgReuseCountSlot()];
  work[sgReuseOffsetSlot()] = offset;
  args[3u * params.objectCount] = min(reused, kMaxGroupsPerRow);
  args[3u * params.objectCount + 1u] = max(1u, (reused + kMaxGroupsPerRow - 1u) / kMaxGroupsPerRow);
  args[3u * params.objectCount + 2u] = 1u;
}
