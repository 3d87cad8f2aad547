// The environment prefilter's bindings, sizes and push constants, declared
// once for C++ (sg::shader) and GLSL.
#ifndef SG_ENVIRONMENT_INTERFACE_H
#define SG_ENVIRONMENT_INTERFACE_H

#include "../../framework/gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kBindEnvSource = 0u;         // the HDR image, RGBA32F texels row by row (storage buffer)
SG_CONST uint kBindEnvSpecularOut = 1u;    // the specular levels, stacked (storage image)
SG_CONST uint kBindEnvIrradianceOut = 2u;  // the irradiance map (storage image)
SG_CONST uint kBindEnvBrdfOut = 3u;        // the split-sum lookup (storage image)

// Equirectangular maps are twice as wide as high. Level 0 of the specular
// maps is the image box-filtered to this size (roughness 0); levels 1..N-1
// are GGX-prefiltered at roughness l / (N - 1). Below the N levels, in
// kEnvSpecularWidth / 4 rows, lie level 0's halvings 1..kEnvPyramidMips side by
// side (halving k at x = W - 2W/2^k): the mips filtered importance sampling reads.
SG_CONST uint kEnvSpecularWidth = 128u;
SG_CONST uint kEnvSpecularLevels = 6u;
SG_CONST uint kEnvPyramidMips = 6u;  // 64x32 down to 2x1
SG_CONST uint kEnvIrradianceWidth = 32u;
SG_CONST uint kEnvBrdfSize = 32u;
SG_CONST uint kEnvSpecularSamples = 128u;  // GGX importance samples per texel of a rough level
SG_CONST uint kEnvBrdfSamples = 256u;

SG_CONST uint kEnvStepDownsample = 0u;   // source -> specular level 0 (level = 0) or its halving `level`
SG_CONST uint kEnvStepBrdf = 1u;         // -> the BRDF lookup
SG_CONST uint kEnvStepIrradiance = 2u;   // specular level 0 -> irradiance
SG_CONST uint kEnvStepSpecular = 3u;     // specular level 0 -> specular level `level`

struct SgEnvironmentPush {
  uint step;
  uint level;
  uint sourceWidth;
  uint sourceHeight;
};

// The background pass (environment_background.comp): the image behind everything, where depth is at the far plane.
SG_CONST uint kBindEnvBackgroundSource = 0u;  // the HDR image, as kBindEnvSource
SG_CONST uint kBindEnvBackgroundDepth = 1u;   // the frame's depth (sampled)
SG_CONST uint kBindEnvBackgroundHdr = 2u;     // the HDR colour, read and written (storage image)

struct SgEnvironmentBackgroundPush {
  mat4 clipToWorld;   // the inverse of the camera's view-projection (clip y up, depth 0..1)
  uvec2 sourceSize;   // the image's width and height
  uvec2 targetSize;   // the HDR colour's
  float intensity;    // cd/m^2 per unit of the image
};

SG_SHARED_END

#endif
