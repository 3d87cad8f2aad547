// Layer "marble-shade": the glTF model lit with the cached marble colour as
// base colour (polished: low roughness).
#include <materials/gltf-pbr/gltf_pbr.glsl>

vec4 shadeMarble(Surface s) {
  vec3 baseColor = sgLayer(marble).rgb;
  return vec4(shadeMetallicRoughness(s, baseColor, 0.0, 0.25, 1.0, vec3(0.0), s.normal), 1.0);
}
