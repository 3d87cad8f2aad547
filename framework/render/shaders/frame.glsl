// Per-frame data: camera and lights (frame_interface.h).
#ifndef SG_FRAME_GLSL
#define SG_FRAME_GLSL

#extension GL_EXT_scalar_block_layout : require
#include "frame_interface.h"

// The names layer authors know.
#define SG_LIGHT_DIRECTIONAL kLightDirectional
#define SG_LIGHT_POINT kLightPoint
#define SG_LIGHT_SPOT kLightSpot
#define SG_MAX_LIGHTS kMaxLights

layout(set = 0, binding = kBindFrame, scalar) uniform Frame { SgFrameUniforms frame; };

// Where a world position lands in this frame's output, in [0, 1]^2 (texture
// coordinates of screen-space frame resources such as an AO image).
vec2 sgScreenUv(vec3 worldPosition) {
  vec4 clip = frame.viewProjection * vec4(worldPosition, 1.0);
  return clip.xy / clip.w * 0.5 + 0.5;
}

#endif
