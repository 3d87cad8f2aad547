#version 460
#define SG_VERTEX_SHADER
#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/object.glsl>

layout(location = 0) out vec3 outPosition;
layout(location = 1) out vec3 outNormal;
#ifndef SG_FORWARD_PLAIN  // plain: position and normal only (forward_surface.glsl)
layout(location = 2) out vec4 outTangent;
layout(location = 3) out vec2 outUv0;
layout(location = 4) out vec2 outUv1;
layout(location = 5) out vec4 outColor;
#endif

void main() {
  // Same `precise` arithmetic as z_prepass.vert: the depths must match exactly.
  precise vec4 world = object.model * vec4(inPosition, 1.0);
  precise vec4 clip = frame.viewProjection * world;
  mat3 normalMatrix = transpose(inverse(mat3(object.model)));
  outPosition = world.xyz;
  outNormal = normalMatrix * inNormal;
#ifndef SG_FORWARD_PLAIN
  // A mirroring model matrix flips cross(normal, tangent): flip the handedness with it.
  float handedness = determinant(mat3(object.model)) < 0.0 ? -1.0 : 1.0;
  outTangent = vec4(mat3(object.model) * inTangent.xyz, inTangent.w * handedness);
  outUv0 = inUv0;
  outUv1 = inUv1;
  outColor = inColor;
#endif
  gl_Position = clip;
}
