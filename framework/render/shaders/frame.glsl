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

// Where a world position lands in this frame's output, in [0, 1]^2 (texture
// coordinates of screen-space frame resources such as an AO image).
vec2 sgScreenUv(vec3 worldPosition) {
  vec4 clip = frame.viewProjection * vec4(worldPosition, 1.0);
  return clip.xy / clip.w * 0.5 + 0.5;
}

#endif
