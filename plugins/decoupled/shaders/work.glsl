// The work buffer: per object its chunk count, the offset of its work list and
// a fill counter, then the work items {entry, chunk, level, physical chunk}.
// Mirrors plugins/decoupled/decoupled_tables.hpp (workBufferBytes).
#ifndef SG_WORK_GLSL
#define SG_WORK_GLSL

layout(set = 0, binding = 8, std430) buffer Work { uint work[]; };

uint sgObjectChunksSlot(uint object) { return object; }
uint sgObjectOffsetSlot(uint object) { return params.objectCount + object; }
uint sgObjectFillSlot(uint object) { return 2u * params.objectCount + object; }
uint sgWorkItemSlot(uint item) { return 3u * params.objectCount + 4u * item; }

#endif
