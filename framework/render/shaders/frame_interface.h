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
// Set 0 of material shaders: the environment light's prefiltered maps (passes/environment), sampled.
SG_CONST uint kBindEnvironmentIrradiance = 41u;  // cosine-convolved radiance, equirectangular
SG_CONST uint kBindEnvironmentSpecular = 42u;    // GGX-prefiltered radiance, one level per roughness step, stacked
SG_CONST uint kBindEnvironmentBrdf = 43u;        // the split-sum BRDF scale and bias by (N.V, roughness)
SG_CONST uint kMaxShadowMaps = 16u;      // maps in the atlas: a spot takes 1, a point light 6 (cube faces), a sun kShadowCascades
SG_CONST uint kShadowCascades = 4u;      // a directional light's maps, near to far
SG_CONST uint kShadowAtlasColumns = 4u;  // maps per atlas row (slot s at column s % 4, row s / 4)
SG_CONST float kCascadeBlend = 0.1f;     // the last tenth of a cascade blends into the next (which covers it too)
SG_CONST uint kBindLights = 48u;      // set 0 of material shaders and shadow maps: Light[counts.x] (storage)
SG_CONST uint kBindLightGrid = 49u;   // set 0 of material shaders: the light grid (light_grid.h; storage)

struct Light {
  vec4 positionType;    // xyz world position, w = type
  vec4 directionRange;  // xyz direction the light travels, w = range (0: infinite)
  vec4 color;           // rgb = colour * intensity
  vec4 cone;            // x = cos(outer), y = 1 / max(cos(inner) - cos(outer), eps), z = shadow map slot + 1 (0: none)
  mat4 shadowMatrix;    // world to the shadow map's clip space (when cone.z > 0; a sun's or point light's first map)
  vec4 cascadeEnds;     // shadowed directional: view depth (along the camera's axis) where cascades 0..3 end
};

struct SgFrameUniforms {
  mat4 view;
  mat4 projection;
  mat4 viewProjection;
  vec4 cameraPosition;
  vec4 ambient;      // rgb ambient radiance
  uvec4 counts;      // x = light count (the lights are at kBindLights), y = output width, z = output height
  vec4 shadowAtlas;  // x = maps in the atlas, y = texels per map side, z = maps per atlas row
  vec4 environment;  // x = 1: image-based lighting from the prefiltered maps (0: the analytic sky), y = intensity (cd/m^2 per unit)
  mat4 shadowMatrices[kMaxShadowMaps];  // world to each map's clip space, by atlas slot
};

// Push constants of a scene draw (render::drawItem).
struct SgObjectConstants {
  mat4 model;
  uint objectId;
  uint materialId;
};

SG_SHARED_END

#endif
