// Per-frame data: camera and lights (set 0, binding 0). Mirrors FrameUniforms in frame_uniforms.hpp.
#ifndef SG_FRAME_GLSL
#define SG_FRAME_GLSL

#define SG_LIGHT_DIRECTIONAL 0u
#define SG_LIGHT_POINT 1u
#define SG_LIGHT_SPOT 2u
#define SG_MAX_LIGHTS 8

struct Light {
  vec4 positionType;    // xyz world position, w = type
  vec4 directionRange;  // xyz direction the light travels, w = range (0: infinite)
  vec4 color;           // rgb = colour * intensity
  vec4 cone;            // x = cos(outer), y = 1 / max(cos(inner) - cos(outer), eps)
};

layout(set = 0, binding = 0, std140) uniform Frame {
  mat4 view;
  mat4 projection;
  mat4 viewProjection;
  vec4 cameraPosition;
  vec4 ambient;      // rgb ambient radiance
  uvec4 counts;      // x = light count, y = output width, z = output height
  Light lights[SG_MAX_LIGHTS];
} frame;

#endif
