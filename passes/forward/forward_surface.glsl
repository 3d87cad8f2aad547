// What the forward (fragment) variant of every material starts from: the
// surface point of this pixel from the vertex shader's varyings, with UV and
// position derivatives per pixel. The framework's generated variant includes
// this, then the authors' sources, then runs the stack and writes the colour.
#ifndef SG_FORWARD_SURFACE_GLSL
#define SG_FORWARD_SURFACE_GLSL

#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/object.glsl>
#include <framework/plugin/shaders/material.glsl>
#include <passes/alpha-mask/alpha_test.glsl>

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
#ifdef SG_FORWARD_PLAIN
// A draw without textures or vertex colours (DrawItem::plainSurface): the
// other attributes are their defaults, not varyings. Lavapipe's per-triangle
// setup and vertex emit cost grows with every varying, and on meshes of
// sub-pixel triangles that cost is most of the frame.
const vec4 inTangent = vec4(1.0, 0.0, 0.0, 1.0);
const vec2 inUv0 = vec2(0.0);
const vec2 inUv1 = vec2(0.0);
const vec4 inColor = vec4(1.0);
#else
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
#endif
layout(location = 0) out vec4 outColor;

// A forward pixel has no shadel level: the level a 1024-shadel chart would
// use here (log2 of the uv0 footprint), so debug layers look alike in both paths.
float sgDetailLevel() {
  vec2 d = max(abs(dFdx(inUv0)), abs(dFdy(inUv0))) * 1024.0;
  return max(0.0, log2(max(max(d.x, d.y), 1e-6)));
}
uint sgTriangleId() { return uint(gl_PrimitiveID); }

Surface sgForwardSurface() {
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
  s.positionDx = dFdx(inPosition);
  s.positionDy = dFdy(inPosition);
  return s;
}

// Last frame's value of a persistent layer: forward keeps no history.
bool sgPrevious(out vec4 value) {
  value = vec4(0.0);
  return false;
}

// The stack's result as the pass wants it: alpha-tested, premultiplied for blending.
// The alpha test is the one decoupled objects get in shadel-mark and composite
// (alpha_test.glsl: the base colour's alpha), so both paths keep the same pixels.
void sgWriteForward(vec4 shaded) {
  shaded.rgb = min(shaded.rgb, vec3(65504.0));  // the HDR target's half-float maximum, not Inf
#ifdef SG_FORWARD_ALPHA_TEST  // alpha-mask draws only: a discard compiled in costs every pixel on lavapipe
  if (sgMaskedOut(inUv0, inUv1, inColor.a)) discard;
#endif
  if (material.flags.x == SG_ALPHA_BLEND)
    outColor = vec4(shaded.rgb * shaded.a, shaded.a);  // premultiplied
  else
    outColor = vec4(shaded.rgb, 1.0);
}

#endif
