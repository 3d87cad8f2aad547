// Colours for debug views: one hue per detail level.
#ifndef SG_DEBUG_COLOR_GLSL
#define SG_DEBUG_COLOR_GLSL
vec3 sgLevelColor(float level) {
  const vec3 colors[8] = vec3[](vec3(0.9, 0.1, 0.1), vec3(1.0, 0.55, 0.0), vec3(0.95, 0.9, 0.1), vec3(0.2, 0.8, 0.2),
                                vec3(0.1, 0.8, 0.9), vec3(0.2, 0.35, 1.0), vec3(0.6, 0.25, 0.9), vec3(0.9, 0.9, 0.9));
  float l = clamp(level, 0.0, 7.0);
  return mix(colors[uint(floor(l))], colors[min(uint(floor(l)) + 1u, 7u)], fract(l));
}
#endif
