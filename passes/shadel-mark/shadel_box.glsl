// Shadel boxes of a chunk as mask bits, and the request shadel-mark writes
// for a bilinear footprint (SG_MARK_REQUESTS) that shadel_mark_requests.comp
// turns back into bits.
#ifndef SG_SHADEL_BOX_GLSL
#define SG_SHADEL_BOX_GLSL

// The shadels of a chunk in the box [lo, hi] (inclusive, inside [0,8)²):
// the row's bits times one bit per row of the box (no carries: row < 256).
uint64_t sgBoxBits(uvec2 lo, uvec2 hi) {
  uint row = ((2u << (hi.x - lo.x)) - 1u) << lo.x;
  uint64_t rows = (uint64_t(0x0101010101010101ul) >> (SG_CHUNK_SIZE * (7u - (hi.y - lo.y)))) << (SG_CHUNK_SIZE * lo.y);
  return uint64_t(row) * rows;
}

// A pixel's request: its footprint's mask slot and the footprint's first tap
// in that chunk (lo; the box is lo..min(lo + 1, 7)), plus one so that 0 (the
// attachment's clear) is no request. Slots stay below 2^26
// (fewer than sg::passes::kMaxRequestEntries owned entries).
uint sgMarkRequest(uint slot, uvec2 lo) { return ((slot << 6u) | (lo.y << 3u) | lo.x) + 1u; }
uint sgRequestSlot(uint request) { return (request - 1u) >> 6u; }
uint64_t sgRequestBits(uint request) {
  uvec2 lo = uvec2((request - 1u) & 7u, ((request - 1u) >> 3u) & 7u);
  return sgBoxBits(lo, min(lo + 1u, uvec2(SG_CHUNK_SIZE - 1u)));
}

#endif
