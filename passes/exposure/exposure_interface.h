// The exposure pass's result and parameters, and the bindings it and tonemap
// share, declared once for C++ (sg::shader) and GLSL.
#ifndef SG_EXPOSURE_INTERFACE_H
#define SG_EXPOSURE_INTERFACE_H

#include "../../framework/gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kBindExposureHdr = 0u;  // the HDR image exposure measures and tonemap maps (sampled)
SG_CONST uint kBindExposure = 1u;     // SgExposure
SG_CONST uint kBindExposureMeter = 2u;  // auto: exposure-meter's log-luminance sum per row band (float[kExposureMeterBands])

// exposure-meter's workgroups: one per band of rows, so the image's reduction
// spreads over every CPU/GPU core rather than one workgroup.
SG_CONST uint kExposureMeterBands = 64u;

SG_CONST uint kExposureAuto = 0u;
SG_CONST uint kExposureManual = 1u;

// Kept across frames (the exposure pass's persistent buffer): automatic
// exposure adapts from last frame's ev100 towards this frame's metering.
struct SgExposure {
  float logAverage;   // natural log of the luminance's geometric mean (auto; 0 in manual)
  float exposure;     // the factor tonemap applies: 1 / (1.2 * 2^ev100)
  float pixels;       // counted (auto; 0 in manual)
  float ev100;        // the exposure value (ISO 100) the frame is shown at
  float targetEv100;  // this frame's metering alone (auto), or the manual value
  uint frames;        // frames exposed so far; 0: no history to adapt from
};

struct SgExposureParams {
  uint mode;           // kExposureAuto or kExposureManual
  float ev100;         // manual: the exposure value
  float compensation;  // auto: EV added to the image's brightness (+1: twice as bright)
  float adaptation;    // auto: fraction of the gap to the metering closed per frame, (0, 1]
  float minEv100;      // auto: the metering's range
  float maxEv100;
};

SG_SHARED_END

#endif
