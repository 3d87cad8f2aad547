#version 460
// Depth of a shadow caster as one shadow map sees it (the map's matrix in the
// frame uniforms' shadowMatrices; which map is a push constant after the object's).
#extension GL_EXT_scalar_block_layout : require
#include <framework/render/shaders/frame.glsl>

layout(push_constant, scalar) uniform ShadowDraw {
  SgObjectConstants object;
  uint slot;
} draw;

// The scene's vertex layout (object.glsl; that file's push constants are not these).
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv0;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;

void main() { gl_Position = frame.shadowMatrices[draw.slot] * (draw.object.model * vec4(inPosition, 1.0)); }
