// The exposure pass's result and the bindings it and tonemap share, declared
// once for C++ (sg::shader) and GLSL.
#ifndef SG_EXPOSURE_INTERFACE_H
#define SG_EXPOSURE_INTERFACE_H

#include "../../framework/gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kBindExposureHdr = 0u;  // the HDR image exposure measures and tonemap maps (sampled)
SG_CONST uint kBindExposure = 1u;     // SgExposure

struct SgExposure {
  float logAverage;  // of the luminance
  float exposure;    // the factor tonemap applies
  float pixels;      // counted
};

SG_SHARED_END

#endif
