#version 460
// Slope-scaled bias, written into the map: the stored depth is pushed back by
// twice the depth change across one texel in x plus one in y. Receivers
// compare against texels up to 2 away in each axis (the 3x3 bilinear PCF of
// lights.glsl), across which a plane's depth changes by at most that much, so
// a lit plane never shadows itself, however grazing the light.
const float kConstantBias = 2e-6;  // depth units: rounding of the receiver's own depth

void main() {
  float z = gl_FragCoord.z;
  gl_FragDepth = min(z + 2.0 * (abs(dFdx(z)) + abs(dFdy(z))) + kConstantBias, 1.0);
}
