#version 460
// Decoupled alpha-mask objects: depth only where the alpha test keeps the
// surface (the same test as forward, shadel-mark and composite).
#include <passes/alpha-mask/alpha_test.glsl>

layout(location = 0) in vec2 inUv0;
layout(location = 1) in vec2 inUv1;
layout(location = 2) in float inColorAlpha;

void main() {
  if (sgMaskedOut(inUv0, inUv1, inColorAlpha)) discard;
}
