#version 460
// Depth of every opaque object, so the colour passes shade each pixel once.
#define SG_VERTEX_SHADER
#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/object.glsl>

void main() {
  // `precise` (no reassociation or fused multiply-add) makes this the same
  // arithmetic as forward.vert, so the forward pass finds exactly these depths.
  precise vec4 world = object.model * vec4(inPosition, 1.0);
  precise vec4 clip = frame.viewProjection * world;
  gl_Position = clip;
}
