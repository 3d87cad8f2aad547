#version 460
// The nearest object's id (the depth test keeps it). With SG_ALPHA_TEST, for
// alpha-mask objects: not where their alpha test cuts them away, so a click
// through a cut-out picks what is behind it.
layout(location = 0) flat in uint inId;
layout(location = 0) out uint outId;

#ifdef SG_ALPHA_TEST
#include <passes/alpha-mask/alpha_test.glsl>
layout(location = 1) in vec2 inUv0;
layout(location = 2) in vec2 inUv1;
layout(location = 3) in float inColorAlpha;
#endif

void main() {
#ifdef SG_ALPHA_TEST
  if (sgMaskedOut(inUv0, inUv1, inColorAlpha)) discard;
#endif
  outId = inId;
}
