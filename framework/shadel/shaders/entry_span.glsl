// The owned remap entries one workgroup of a per-entry pass covers: a run of
// the frame's live entries (SgEntrySpan, pushed by passes::dispatchEntrySpans),
// its workgroups a 2D grid (x up to 65535) read back as one index; or, with
// sgEntrySpan.blocks, one of the frame's live entry blocks (live-entry-blocks:
// the live spans without the objects the occlusion cull hid this frame and
// last frame), dispatched indirectly.
#ifndef SG_ENTRY_SPAN_GLSL
#define SG_ENTRY_SPAN_GLSL

#include "decoupled_interface.h"

layout(push_constant, scalar) uniform EntrySpanPush { SgEntrySpan sgEntrySpan; };
layout(set = 0, binding = kBindEntryBlocks, scalar) readonly buffer EntryBlocks {
  SgEntryBlocksHeader entryBlocksHeader;
  SgEntryBlock entryBlocks[];
};

uint sgSpanWorkgroup() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

uint sgSpanEnd = 0u;  // this workgroup's end: its span's (set by sgSpanGroupFirst)

// The first owned entry of this workgroup, which covers `perGroup` entries
// (64 or 32: a block is kEntryBlockSize).
uint sgSpanGroupFirst(uint perGroup) {
  uint w = sgSpanWorkgroup();
  if (sgEntrySpan.blocks == 0u) {
    sgSpanEnd = sgEntrySpan.end;
    return sgEntrySpan.begin + w * perGroup;
  }
  uint perBlock = kEntryBlockSize / perGroup;
  SgEntryBlock block = entryBlocks[w / perBlock];
  sgSpanEnd = block.spanEnd;
  return block.first + (w % perBlock) * perGroup;
}

// The owned entry of this invocation, one entry per invocation of workgroups
// of `groupSize` (given: gl_WorkGroupSize is not yet declared where this is included).
uint sgSpanEntry(uint groupSize) { return sgSpanGroupFirst(groupSize) + gl_LocalInvocationIndex; }

// Call after sgSpanGroupFirst or sgSpanEntry.
bool sgInSpan(uint ownedIndex) { return ownedIndex < sgSpanEnd; }

#endif
