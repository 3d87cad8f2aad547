// Layers "blur-u" and "blur-v": one axis of a separable Gaussian blur of an
// earlier layer in shadel space (decoupled only; the paper's skin example
// blurs diffuse light this way). The kernel is in shadels of the shaded level,
// which the level selection keeps near one per pixel: a screen-sized blur.
// Parameters: BLUR_INPUT (layer), BLUR_AXIS (ivec2 step), BLUR_RADIUS (int),
// BLUR_SIGMA (shadels).
vec4 blurLayer(Surface s) {
  vec4 sum = vec4(0.0);
  float total = 0.0;
  for (int i = -BLUR_RADIUS; i <= BLUR_RADIUS; ++i) {
    float w = exp(-0.5 * float(i * i) / (BLUR_SIGMA * BLUR_SIGMA));
    sum += w * sgLayerAt(BLUR_INPUT, BLUR_AXIS * i);
    total += w;
  }
  return sum / total;
}
