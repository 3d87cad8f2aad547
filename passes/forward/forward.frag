#version 460
// Forward shading of one object with its glTF material. With the z-prepass,
// opaque objects run with an EQUAL depth test: one shade per visible pixel.
#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/object.glsl>
#include <materials/gltf-pbr/material.glsl>
#include <materials/gltf-pbr/gltf_pbr.glsl>

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
layout(location = 0) out vec4 outColor;

void main() {
  Surface s;
  s.position = inPosition;
  s.normal = normalize(inNormal);
  if (!gl_FrontFacing) s.normal = -s.normal;  // double-sided back faces (others are culled)
  s.tangent = inTangent;
  s.uv0 = inUv0;
  s.uv1 = inUv1;
  s.color = inColor;
  s.uv0Dx = dFdx(inUv0);
  s.uv0Dy = dFdy(inUv0);
  s.uv1Dx = dFdx(inUv1);
  s.uv1Dy = dFdy(inUv1);
  vec4 shaded = shadeGltfPbr(s);
  if (material.flags.x == SG_ALPHA_MASK && shaded.a < material.params.w) discard;
  if (material.flags.x == SG_ALPHA_BLEND)
    outColor = vec4(shaded.rgb * shaded.a, shaded.a);  // premultiplied
  else
    outColor = vec4(shaded.rgb, 1.0);
}
