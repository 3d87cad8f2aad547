// The work buffer (decoupled_interface.h): per object its chunk count, the
// offset of its work list and a fill counter, then the work items
// {entry, chunk, level, physical chunk}.
#ifndef SG_WORK_GLSL
#define SG_WORK_GLSL

#include "decoupled.glsl"

layout(set = 0, binding = kBindWork, std430) buffer Work { uint work[]; };

uint sgObjectChunksSlot(uint object) { return object; }
uint sgObjectOffsetSlot(uint object) { return params.objectCount + object; }
uint sgObjectFillSlot(uint object) { return 2u * params.objectCount + object; }
uint sgWorkItemSlot(uint item) { return kWorkSlotsPerObject * params.objectCount + kWorkSlotsPerItem * item; }

#endif
