// The glTF 2.0 metallic-roughness BRDF (spec appendix B): GGX / Trowbridge-Reitz
// distribution, height-correlated Smith visibility, Schlick Fresnel, Lambert diffuse.
#ifndef SG_BRDF_GLSL
#define SG_BRDF_GLSL

const float kPi = 3.14159265358979;

float distributionGgx(float NdotH, float alpha) {
  float a2 = alpha * alpha;
  float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}

float visibilitySmithGgx(float NdotL, float NdotV, float alpha) {
  float a2 = alpha * alpha;
  float gv = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
  float gl = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
  float g = gv + gl;
  return g > 0.0 ? 0.5 / g : 0.0;
}

vec3 fresnelSchlick(vec3 f0, float VdotH) { return f0 + (1.0 - f0) * pow(1.0 - VdotH, 5.0); }
vec3 fresnelSchlick(vec3 f0, float f90, float VdotH) { return f0 + (f90 - f0) * pow(1.0 - VdotH, 5.0); }

// Radiance reflected towards V from one light of radiance `light` arriving along L,
// with the dielectric Fresnel at normal and grazing incidence given
// (KHR_materials_ior / KHR_materials_specular; glTF's default is 0.04 and 1).
vec3 brdfGltf(vec3 baseColor, float metallic, float roughness, vec3 dielectricF0, float dielectricF90, vec3 N, vec3 V,
              vec3 L, vec3 light) {
  vec3 H = normalize(V + L);
  float NdotL = clamp(dot(N, L), 0.0, 1.0);
  float NdotV = clamp(abs(dot(N, V)), 1e-4, 1.0);
  float NdotH = clamp(dot(N, H), 0.0, 1.0);
  float VdotH = clamp(dot(V, H), 0.0, 1.0);
  float alpha = max(roughness * roughness, 1e-3);
  vec3 f0 = mix(dielectricF0, baseColor, metallic);
  vec3 F = fresnelSchlick(f0, mix(dielectricF90, 1.0, metallic), VdotH);
  vec3 diffuse = (1.0 - F) * (1.0 - metallic) * baseColor / kPi;
  vec3 specular = F * distributionGgx(NdotH, alpha) * visibilitySmithGgx(NdotL, NdotV, alpha);
  return (diffuse + specular) * light * NdotL;
}

#endif
