// The bloom pass's bindings and push constants, declared once for C++ (sg::shader) and GLSL.
#ifndef SG_BLOOM_INTERFACE_H
#define SG_BLOOM_INTERFACE_H

#include "../../framework/gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kBindBloomHdr = 0u;       // the HDR colour (sampled, fetched texel by texel)
SG_CONST uint kBindBloomExposure = 1u;  // SgExposure (passes/exposure), this frame's
SG_CONST uint kBindBloomSource = 2u;    // the level read (storage image)
SG_CONST uint kBindBloomTarget = 3u;    // the level or image written (storage image)

SG_CONST uint kBloomStepBright = 0u;     // HDR colour -> level 1: the part above white after exposure, 2x2 box
SG_CONST uint kBloomStepDown = 1u;       // level i-1 -> level i, 2x2 box
SG_CONST uint kBloomStepUp = 2u;         // level i -> level i-1, added, bilinear (tent over the pyramid)
SG_CONST uint kBloomStepCombine = 3u;    // HDR colour + strength * level 1 / levels -> the bloomed HDR colour

struct SgBloomPush {
  uint step;
  float strength;
  uint levels;
};

SG_SHARED_END

#endif
