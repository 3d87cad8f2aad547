// The set-0 bindings every decoupled-shading pass shares, declared with the
// numbers and records of decoupled_interface.h (each pass's pipeline layout
// lists the ones it uses).
#ifndef SG_DECOUPLED_GLSL
#define SG_DECOUPLED_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_scalar_block_layout : require

#include "decoupled_interface.h"
#include "shadel_level.glsl"

layout(set = 0, binding = kBindParams, scalar) uniform DecoupledParams { SgDecoupledParams params; };
layout(set = 0, binding = kBindObjects, scalar) readonly buffer Objects { SgDecoupledObject objects[]; };
layout(set = 0, binding = kBindShadelInstances, std430) readonly buffer ShadelInstances { SgShadelInstance shadelInstances[]; };
layout(set = 0, binding = kBindLevelRects, std430) readonly buffer LevelRects { SgLevelRect levelRects[]; };
layout(set = 0, binding = kBindRemap, std430) buffer Remap { SgRemapEntry remap[]; };
layout(set = 0, binding = kBindOwnedEntries, std430) readonly buffer OwnedEntries { SgOwnedEntry ownedEntries[]; };
layout(set = 0, binding = kBindCounters, scalar) buffer Counters { SgShadeCounters counters; };

SgLevelRect sgLevelRect(uint object, uint level) { return levelRects[shadelInstances[object].firstLevelRect + level]; }

#include "chunk_slots.glsl"

#endif
