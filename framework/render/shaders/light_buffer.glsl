// The frame's lights (frame.counts.x of them; frame_interface.h), a storage
// buffer so a frame may hold up to kMaxLights.
#ifndef SG_LIGHT_BUFFER_GLSL
#define SG_LIGHT_BUFFER_GLSL

#extension GL_EXT_scalar_block_layout : require
#include "frame_interface.h"

layout(set = 0, binding = kBindLights, scalar) readonly buffer SgLightBuffer { Light sgLights[]; };

#endif
