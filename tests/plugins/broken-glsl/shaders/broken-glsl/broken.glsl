// A layer with a mistake an author makes: an undeclared name on line 6.
#include <framework/render/shaders/frame.glsl>

vec4 brokenLayer(Surface s) {
  vec3 tint = s.normal * 0.5 + 0.5;
  return vec4(tint * brightnes, 1.0);
}
