// Layer "marble" (persistent): an expensive procedural marble colour from many
// octaves of 3D value noise at the object-space-independent world position.
// It does not depend on the view, so a shadel shaded last frame keeps its
// value (sgPrevious) and only newly visible shadels pay for the noise.
// Parameter: MARBLE_OCTAVES (at most; fewer where the sample footprint is large).
#ifndef SG_MARBLE_GLSL
#define SG_MARBLE_GLSL

float marbleHash(vec3 p) {
  p = fract(p * 0.3183099 + 0.1);
  p *= 17.0;
  return fract(p.x * p.y * p.z * (p.x + p.y + p.z));
}

float valueNoise(vec3 p) {
  vec3 i = floor(p), f = fract(p);
  f = f * f * (3.0 - 2.0 * f);
  return mix(mix(mix(marbleHash(i), marbleHash(i + vec3(1, 0, 0)), f.x),
                 mix(marbleHash(i + vec3(0, 1, 0)), marbleHash(i + vec3(1, 1, 0)), f.x), f.y),
             mix(mix(marbleHash(i + vec3(0, 0, 1)), marbleHash(i + vec3(1, 0, 1)), f.x),
                 mix(marbleHash(i + vec3(0, 1, 1)), marbleHash(i + vec3(1, 1, 1)), f.x), f.y),
             f.z);
}

vec4 marbleColor(Surface s) {
  vec4 cached;
  if (sgPrevious(cached)) return cached;
  vec3 p = s.position * 3.0;
  // Band-limited by the sample's footprint (the position derivatives): an
  // octave finer than half a sample fades out instead of aliasing, so shadels
  // and pixels converge to the same pattern.
  float footprint = 3.0 * max(length(s.positionDx), length(s.positionDy));
  float turbulence = 0.0, amplitude = 0.5, frequency = 1.0;
  for (int octave = 0; octave < MARBLE_OCTAVES; ++octave) {
    float fade = clamp(2.0 - 4.0 * frequency * footprint, 0.0, 1.0);
    turbulence += fade * amplitude * abs(valueNoise(p) * 2.0 - 1.0);
    p *= 2.03;
    frequency *= 2.03;
    amplitude *= 0.5;
  }
  float vein = 0.5 + 0.5 * sin(s.position.x * 4.0 + 8.0 * turbulence);
  vec3 color = mix(vec3(0.25, 0.22, 0.2), vec3(0.92, 0.9, 0.86), pow(vein, 0.6));
  return vec4(color, 1.0);
}

#endif
