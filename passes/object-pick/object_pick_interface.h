// The object-pick pass's push constants after the draw's own, declared once
// for C++ (sg::shader) and GLSL.
#ifndef SG_OBJECT_PICK_INTERFACE_H
#define SG_OBJECT_PICK_INTERFACE_H

#include "../../framework/gpu/shaders/shared.h"

SG_SHARED_BEGIN

// Which pixel the 1x1 target stands for: clip.xy = (clip.xy - center * clip.w) * scale
// makes that pixel of the full frame the whole target.
struct SgPickWindow {
  vec2 center;  // the picked pixel's centre in the frame's clip space (x right, +y up)
  vec2 scale;   // the frame's size in pixels: one pixel becomes clip space's width 2
};

SG_SHARED_END

#endif
