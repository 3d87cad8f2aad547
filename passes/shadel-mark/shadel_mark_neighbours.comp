#version 460
// shadel-mark's second step where its fragment shader marks only the shadel
// mask of each footprint's own chunk (shadel masks with the bilinear or
// trilinear filter: SG_MARK_OWN_CHUNK_ONLY): the shadels a footprint reads
// through its tile's gutter, in the chunks right of, below and diagonally
// after it, added to those chunks' masks.
// The fragment shader's box for a footprint at tile shadel lo (in its chunk)
// is lo..min(lo + 1, 7). A footprint at lo.x == 7 also reads column 0 of the
// chunk to the right at its box's rows; lo.y == 7 row 0 of the chunk below;
// lo == (7, 7) the diagonal chunk's shadel (0, 0). Its own box has the same
// rows (columns) in its column 7 (row 7), so each chunk takes column 0 from
// its left neighbour's column 7, row 0 from its upper neighbour's row 7 and
// (0, 0) from the diagonal's (7, 7), read from rows and columns >= 1 only
// (row 0 of column 7 stands in for row 1's: a box holds both), which this
// step never writes: every thread reads only what the fragment shader wrote,
// whatever order they run in. A superset of what the fragment shader used to
// add to the neighbours (column 7 also holds boxes at lo.x == 6): a few more
// shadels shaded at the edges of what is visible at a level, the same ones read.
// Only chunks with storage need their gutter shadels: a thread per owned
// entry of the live span (entry_span.glsl), like shadel-clear's, visits its
// entry's marked chunks and writes only their masks. Before, the fragment
// shader did this per pixel: up to three neighbour chunks' mask reads and
// atomics in a loop (each a loop over the lanes on lavapipe, run as often as
// the lane with the most chunks needed).
// The thread first sets its entry's occupancy (shadel-clear zeroed it): a
// chunk is marked when the fragment shader set any bit of its mask (its
// own-chunk box is never empty), so the fragment shader needs no occupancy
// read and atomic per pixel. No other thread writes this entry's masks, so
// what it reads first is what the fragment shader marked.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/entry_span.glsl>

layout(local_size_x = 64) in;
layout(set = 0, binding = kBindShadelMasks, std430) buffer ShadelMasks { uint64_t shadelMasks[]; };
layout(set = 0, binding = kBindShadelMaskPairTexels) uniform usamplerBuffer shadelMaskPairs;  // RGBA32UI: two masks a texel

const uint64_t kColumn0BelowRow0 = uint64_t(0x0101010101010100ul);  // shadels (0, y), y >= 1 (bit y * 8 + x)

// The mask of the level's chunk at `chunk` (in chunks from the level's
// origin); this thread's entry is owned entry `ownedIndex` at `entry` (in
// entries from the level's origin). A level's owned entries are a square of
// `side` a side, row-major (shadel_mark_levels.glsl).
uint64_t sgMaskOf(uint ownedIndex, uvec2 entry, uint side, uvec2 chunk) {
  uvec2 other = chunk >> 3u;
  uint index = ownedIndex + (other.y - entry.y) * side + (other.x - entry.x);
  return shadelMasks[index * SG_CHUNKS_PER_ENTRY + (chunk.y & 7u) * SG_ENTRY_CHUNKS + (chunk.x & 7u)];
}

void main() {
  uint i = sgSpanEntry(64u);
  if (!sgInSpan(i)) return;
  // The masks two at a time through a texel view: a gather each on
  // lavapipe, where a storage-buffer read is a loop over the lanes.
  uint64_t marked = uint64_t(0);
  for (uint c = 0u; c < SG_CHUNKS_PER_ENTRY; c += 2u) {
    uvec4 pair = texelFetch(shadelMaskPairs, int((i * SG_CHUNKS_PER_ENTRY + c) >> 1u));
    uint two = uint((pair.x | pair.y) != 0u) | (uint((pair.z | pair.w) != 0u) << 1u);
    marked |= uint64_t(two) << c;
  }
  if (marked == uint64_t(0)) return;
  SgOwnedEntry owned = ownedEntries[i];
  remap[owned.entryIndex].occupancy = marked;
  SgLevelRect rect = sgLevelRect(owned.instanceId, owned.level);
  uint side = max(rect.size >> SG_ENTRY_SIZE_LOG2, 1u);
  uvec2 entry = (sgVirtualShadel(SgShadelAddress(owned.entryIndex, 0u, 0u), params.entriesPerSideLog2) - rect.origin) >>
                SG_ENTRY_SIZE_LOG2;
  for (; marked != uint64_t(0); marked &= marked - uint64_t(1)) {
    uvec2 halves = unpackUint2x32(marked);
    uint c = halves.x != 0u ? uint(findLSB(halves.x)) : 32u + uint(findLSB(halves.y));
    uvec2 chunk = entry * SG_ENTRY_CHUNKS + uvec2(c & 7u, c >> 3u);  // from the level's origin
    uint64_t left = chunk.x > 0u ? sgMaskOf(i, entry, side, chunk - uvec2(1u, 0u)) : uint64_t(0);
    uint64_t above = chunk.y > 0u ? sgMaskOf(i, entry, side, chunk - uvec2(0u, 1u)) : uint64_t(0);
    uint64_t diagonal = chunk.x > 0u && chunk.y > 0u ? sgMaskOf(i, entry, side, chunk - 1u) : uint64_t(0);
    uint64_t gutter = ((left >> 7u) & kColumn0BelowRow0) | ((left >> 15u) & uint64_t(1u)) |
                      ((above >> 56u) & uint64_t(0xFEu)) | ((above >> 57u) & uint64_t(1u)) | (diagonal >> 63u);
    uint slot = i * SG_CHUNKS_PER_ENTRY + c;
    uint64_t mask = shadelMasks[slot];
    if ((mask | gutter) != mask) shadelMasks[slot] = mask | gutter;
  }
}
