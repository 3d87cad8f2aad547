// The frame uniforms (camera, light count), the lights (a storage buffer) and
// the per-draw push constants every pass that draws scene geometry uses,
// declared once for C++ (sg::shader) and GLSL (framework/gpu/shaders/shared.h).
#ifndef SG_FRAME_INTERFACE_H
#define SG_FRAME_INTERFACE_H

#include "../../gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kBindFrame = 0u;  // set 0: SgFrameUniforms (uniform)

SG_CONST uint kLightDirectional = 0u;
SG_CONST uint kLightPoint = 1u;
SG_CONST uint kLightSpot = 2u;
// The most lights a frame holds (a scene with more is an error naming both
// numbers): 4096 records of 128 bytes, 512 KiB per frame in flight.
SG_CONST uint kMaxLights = 4096u;
SG_CONST uint kBindShadowMaps = 40u;  // set 0 of material shaders: the shadow atlas (depth, sampled)
SG_CONST uint kBindLights = 48u;      // set 0 of material shaders and shadow maps: Light[counts.x] (storage)
SG_CONST uint kBindLightGrid = 49u;   // set 0 of material shaders: the light grid (light_grid.h; storage)

struct Light {
  vec4 positionType;    // xyz world position, w = type
  vec4 directionRange;  // xyz direction the light travels, w = range (0: infinite)
  vec4 color;           // rgb = colour * intensity
  vec4 cone;            // x = cos(outer), y = 1 / max(cos(inner) - cos(outer), eps), z = shadow map slot + 1 (0: none)
  mat4 shadowMatrix;    // world to the shadow map's clip space (when cone.z > 0)
};

struct SgFrameUniforms {
  mat4 view;
  mat4 projection;
  mat4 viewProjection;
  vec4 cameraPosition;
  vec4 ambient;      // rgb ambient radiance
  uvec4 counts;      // x = light count (the lights are at kBindLights), y = output width, z = output height
  vec4 shadowAtlas;  // x = maps side by side in the atlas, y = texels per map side
};

// Push constants of a scene draw (render::drawItem).
struct SgObjectConstants {
  mat4 model;
  uint objectId;
  uint materialId;
};

SG_SHARED_END

#endif
