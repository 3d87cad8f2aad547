// Layer "gltf-pbr-specular": gltf-pbr with the dielectric Fresnel the layer
// under it (dielectric-specular) computed from KHR_materials_ior / _specular.
#include <materials/gltf-pbr/gltf_pbr.glsl>

vec4 shadeGltfPbrSpecular(Surface s) {
  vec4 fresnel = sgLayer(dielectric_specular);
  return shadeGltfPbrWithFresnel(s, fresnel.rgb, fresnel.a);
}
