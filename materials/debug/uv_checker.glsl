// Layer "uv-checker": an 8x8 checker on uv0 with a red/green gradient (u, v),
// unlit: shows the UV layout and its orientation.
vec4 uvChecker(Surface s) {
  vec2 cell = floor(s.uv0 * 8.0);
  float check = mod(cell.x + cell.y, 2.0);
  vec3 gradient = vec3(fract(s.uv0), 0.3);
  return vec4(mix(gradient * 0.35, gradient, check), 1.0);
}
