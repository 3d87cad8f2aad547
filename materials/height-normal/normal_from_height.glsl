// Layer "normal-from-height" (decoupled only, reads "height" with radius 1):
// the height's central differences between neighbouring shadels.
#include "bump.glsl"

vec4 normalFromHeight(Surface s) {
  float dx = 0.5 * (sgLayerAt(height, ivec2(1, 0)).r - sgLayerAt(height, ivec2(-1, 0)).r);
  float dy = 0.5 * (sgLayerAt(height, ivec2(0, 1)).r - sgLayerAt(height, ivec2(0, -1)).r);
  return shadeBumped(s, dx, dy);
}
