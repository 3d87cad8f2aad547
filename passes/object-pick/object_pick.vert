#version 460
// The scene's draws as seen through one pixel of the frame: the frame's
// camera, then the picked pixel stretched over the 1x1 target.
#extension GL_EXT_scalar_block_layout : require
#include <framework/render/shaders/frame.glsl>
#include "object_pick_interface.h"

layout(push_constant, scalar) uniform Pick {
  SgObjectConstants object;  // objectId: the scene instance + 1
  SgPickWindow window;
};

// The scene's vertex layout (object.glsl's, whose push constants this pass extends).
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
layout(location = 0) flat out uint outId;
#ifdef SG_ALPHA_TEST
layout(location = 1) out vec2 outUv0;
layout(location = 2) out vec2 outUv1;
layout(location = 3) out float outColorAlpha;
#endif

void main() {
  vec4 clip = frame.viewProjection * (object.model * vec4(inPosition, 1.0));
  clip.xy = (clip.xy - window.center * clip.w) * window.scale;
  gl_Position = clip;
  outId = object.objectId;
#ifdef SG_ALPHA_TEST
  outUv0 = inUv0;
  outUv1 = inUv1;
  outColorAlpha = inColor.a;
#endif
}
