// Layer "triangle-id": a colour per triangle (decoupled: from the triangle-ID
// map; forward: gl_PrimitiveID of the draw). Shows what each shadel was
// interpolated from.
vec4 triangleIdColor(Surface s) {
  uint h = sgTriangleId() * 2654435761u;
  h ^= h >> 15u;
  return vec4(vec3(h & 255u, (h >> 8u) & 255u, (h >> 16u) & 255u) / 255.0 * 0.8 + 0.2, 1.0);
}
