// The owned remap entries one dispatch of a per-entry pass covers: a run of the
// frame's live entries (SgEntrySpan, pushed by passes::dispatchEntrySpans),
// its workgroups a 2D grid (x up to 65535) read back as one index.
#ifndef SG_ENTRY_SPAN_GLSL
#define SG_ENTRY_SPAN_GLSL

#include "decoupled_interface.h"

layout(push_constant, scalar) uniform EntrySpanPush { SgEntrySpan sgEntrySpan; };

uint sgSpanWorkgroup() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

// The first owned entry of this workgroup, which covers `perGroup` entries.
uint sgSpanGroupFirst(uint perGroup) { return sgEntrySpan.begin + sgSpanWorkgroup() * perGroup; }

// The owned entry of this invocation, one entry per invocation of workgroups
// of `groupSize` (given: gl_WorkGroupSize is not yet declared where this is included).
uint sgSpanEntry(uint groupSize) { return sgSpanGroupFirst(groupSize) + gl_LocalInvocationIndex; }

bool sgInSpan(uint ownedIndex) { return ownedIndex < sgEntrySpan.end; }

#endif
