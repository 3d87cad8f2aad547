// Layer "normal-from-height-screen" (forward only): the forward fallback of
// "normal-from-height". A pixel has no neighbours to read, but the height's
// screen derivatives give the same bump from the same formula.
#include "bump.glsl"

vec4 normalFromHeightScreen(Surface s) {
  float h = sgLayer(height).r;
  return shadeBumped(s, dFdx(h), dFdy(h));
}
