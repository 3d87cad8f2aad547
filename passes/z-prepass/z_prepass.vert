#version 460
// Depth of every opaque object, so the colour passes shade each pixel once;
// with SG_ALPHA_TEST, of decoupled alpha-mask objects where their alpha test
// keeps them (z_prepass_alpha_test.frag), so they hide what is behind them.
#define SG_VERTEX_SHADER
#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/object.glsl>

#ifdef SG_ALPHA_TEST
layout(location = 0) out vec2 outUv0;
layout(location = 1) out vec2 outUv1;
layout(location = 2) out float outColorAlpha;
#endif

void main() {
  // `precise` (no reassociation or fused multiply-add) makes this the same
  // arithmetic as forward.vert, so the forward pass finds exactly these depths.
  precise vec4 world = object.model * vec4(inPosition, 1.0);
  precise vec4 clip = frame.viewProjection * world;
  gl_Position = clip;
#ifdef SG_ALPHA_TEST
  outUv0 = inUv0;
  outUv1 = inUv1;
  outColorAlpha = inColor.a;
#endif
}
