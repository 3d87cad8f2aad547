// Layer "specular-light" (view-dependent, the stack's last): the diffuse
// layer's radiance plus glTF PBR's specular reflection of the lights and the
// environment towards the camera.
#include <materials/split-pbr/diffuse_light.glsl>

vec4 specularLight(Surface s) {
  vec4 diffuse = sgLayer(diffuse_light);
  if (material.flags.w != 0u) return diffuse;  // unlit: the diffuse layer returned the base colour
  SplitInputs m = splitInputs(s);
  vec3 V = normalize(frame.cameraPosition.xyz - s.position);
  float alpha = max(m.roughness * m.roughness, 1e-3);
  vec3 f0 = mix(vec3(0.04), m.baseColor.rgb, m.metallic);
  float NdotV = clamp(abs(dot(m.N, V)), 1e-4, 1.0);
  vec3 color = diffuse.rgb;
  SgLightList lights = sgLightsAt(s.position);
  for (uint k = 0u; k < lights.count; ++k) {
    LightSample light = sgLightAt(sgLight(lights, k), s.position);
    vec3 H = normalize(V + light.direction);
    float NdotL = clamp(dot(m.N, light.direction), 0.0, 1.0);
    vec3 F = fresnelSchlick(f0, clamp(dot(V, H), 0.0, 1.0));
    color += F * distributionGgx(clamp(dot(m.N, H), 0.0, 1.0), alpha) * visibilitySmithGgx(NdotL, NdotV, alpha) *
             light.radiance * NdotL;
  }
  // The environment's specular term, as shadeMetallicRoughness computes it.
  color += m.occlusion * ambientSpecular(reflect(-V, m.N), NdotV, m.roughness, f0);
  return vec4(color, diffuse.a);
}
