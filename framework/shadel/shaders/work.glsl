// The work buffer (decoupled_interface.h): per object its chunk count, the
// offset of its work list and a fill counter, then the reuse list's count,
// offset and fill counter, then the work items: {entry, chunk, level,
// physical chunk} to shade, followed by {previous physical, physical, -, -}
// to copy from last frame's storage.
#ifndef SG_WORK_GLSL
#define SG_WORK_GLSL

#include "decoupled.glsl"

layout(set = 0, binding = kBindWork, std430) buffer Work { uint work[]; };

uint sgObjectChunksSlot(uint object) { return object; }
uint sgObjectOffsetSlot(uint object) { return params.objectCount + object; }
uint sgObjectFillSlot(uint object) { return 2u * params.objectCount + object; }
uint sgReuseCountSlot() { return kWorkSlotsPerObject * params.objectCount; }
uint sgReuseOffsetSlot() { return kWorkSlotsPerObject * params.objectCount + 1u; }
uint sgReuseFillSlot() { return kWorkSlotsPerObject * params.objectCount + 2u; }
uint sgWorkItemSlot(uint item) {
  return kWorkSlotsPerObject * params.objectCount + kWorkGlobalSlots + kWorkSlotsPerItem * item;
}

#endif
