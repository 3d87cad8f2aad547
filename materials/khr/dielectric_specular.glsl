// Layer "dielectric-specular": the dielectric Fresnel of KHR_materials_ior and
// KHR_materials_specular, an input of the base layer under it
// (gltf-pbr-specular). rgb = f0 = min(((ior-1)/(ior+1))^2 * specularColor, 1)
// * specular, a = f90 = specular (the extensions' spec, "Implementation").
// A function of the surface's textures alone: kept across shade frames.
#include <framework/plugin/shaders/material.glsl>

vec4 dielectricSpecular(Surface s) {
  vec3 color = material.specular.rgb;  // specularColorFactor x the ior's f0
  if (materialHas(SG_TEX_SPECULAR_COLOR)) color *= materialSample(specularColorTexture, SG_TEX_SPECULAR_COLOR, s).rgb;
  float weight = material.specular.w;
  if (materialHas(SG_TEX_SPECULAR)) weight *= materialSample(specularTexture, SG_TEX_SPECULAR, s).a;
  return vec4(min(color, vec3(1.0)) * weight, weight);
}
