// Layer-shade packs the shadels composite reads into full lanes: invocation i
// of n shades the i-th, (i + n)-th, ... marked shadel of its chunk, so no pass
// over the lanes is spent on masked-out shadels (on lavapipe a masked lane
// costs its pass as much as a shading one, and the default scene's chunks
// have about a third of their shadels masked out). Each invocation walks the
// mask by clearing its lowest set bits: cheaper on lavapipe's 8-wide vectors
// than finding the n-th set bit by popcounts (no vector popcount in AVX2).
#ifndef SG_MARKED_SHADELS_GLSL
#define SG_MARKED_SHADELS_GLSL

// Needs GL_EXT_shader_explicit_arithmetic_types_int64 (decoupled.glsl enables it).

// `left` without its `count` lowest set bits.
uint64_t sgSkipMarked(uint64_t left, uint count) {
  for (uint k = 0u; k < count; ++k) left &= left - 1ul;
  return left;
}

// The texel index (8x8 row-major, = bit) of the lowest set bit; left != 0.
uint sgFirstMarkedTexel(uint64_t left) {
  uvec2 halves = unpackUint2x32(left);
  return halves.x != 0u ? uint(findLSB(halves.x)) : 32u + uint(findLSB(halves.y));
}

#endif
