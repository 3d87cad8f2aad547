#version 460
// support-expand: marks the chunks around the ones shadel-mark marked, for
// objects whose layers read neighbours (objects[].supportChunks > 0: every
// chunk within that many chunks, the 8-neighbourhood for 1), at the same level
// and only inside the same level rectangle. The twin of
// framework/shadel/support_expand.cpp.
//
// Two dispatches of this file, so that nothing cascades: a chunk is added only
// because a chunk marked *by shadel-mark* is near it.
//   gather (the default): a thread per owned entry of the live span (entry_span.glsl); reads the original
//     occupancy of its entry and of the 8 around it (radius <= 8 chunks, an
//     entry's side), dilates it with 64-bit row and column shifts (a box:
//     rows, then columns) and writes the entry's mask to supportMasks. It
//     writes no occupancy, so every read sees shadel-mark's bits. (A
//     workgroup per entry, a thread per chunk testing its (2r+1)^2
//     neighbours, read each neighbour's remap entry once per chunk.)
//   apply (SG_SUPPORT_APPLY defined): a thread per owned entry ORs its mask into the entry
//     (owned entries are distinct: no atomics) and counts the new bits.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/entry_span.glsl>

// The transient buffer of the masks, one per owned entry.
layout(set = 0, binding = kBindSupportMasks, std430) buffer SupportMasks { uint64_t supportMasks[]; };

const uint SG_MAX_SUPPORT_CHUNKS = 8u;  // sg::shadel::kMaxSupportChunks

#ifndef SG_SUPPORT_APPLY
layout(local_size_x = 64) in;

// An 8-bit row pattern repeated in all 8 rows of an entry's mask (bit y * 8 + x: chunk x, y).
uint64_t sgEveryRow(uint bits) { return uint64_t(bits & 0xFFu) * 0x0101010101010101ul; }

// The chunks of the entry at `entry` (in entries) inside the chunk span [begin, end)
// (ChunkSpan::contains over sg::shadel::chunkSpanOf(rect)).
uint64_t sgSpanMask(ivec2 entry, ivec2 begin, ivec2 end) {
  ivec2 lo = clamp(begin - entry * int(SG_ENTRY_CHUNKS), ivec2(0), ivec2(8));
  ivec2 hi = clamp(end - entry * int(SG_ENTRY_CHUNKS), ivec2(0), ivec2(8));
  if (lo.x >= hi.x || lo.y >= hi.y) return uint64_t(0);
  uint columns = ((1u << uint(hi.x)) - 1u) & ~((1u << uint(lo.x)) - 1u);
  uint64_t below = hi.y == 8 ? ~uint64_t(0) : (uint64_t(1) << uint(8 * hi.y)) - uint64_t(1);
  uint64_t above = (uint64_t(1) << uint(8 * lo.y)) - uint64_t(1);
  return sgEveryRow(columns) & below & ~above;
}

// Each chunk of `centre` set if a chunk within `radius` rows of it is set, in
// `centre` or in the entries above and below it.
uint64_t sgDilateRows(uint64_t above, uint64_t centre, uint64_t below, uint radius) {
  uint64_t m = centre;
  for (uint k = 1u; k <= radius; ++k) {
    if (k < 8u) {
      uint s = 8u * k;
      m |= (centre << s) | (centre >> s) | (above >> (64u - s)) | (below << (64u - s));
    } else {
      m |= above | below;  // 8 rows away: the same row of the entries above and below
    }
  }
  return m;
}

// The same along rows: within `radius` columns, in `centre` or the entries left and right of it.
uint64_t sgDilateColumns(uint64_t left, uint64_t centre, uint64_t right, uint radius) {
  uint64_t m = centre;
  for (uint k = 1u; k <= radius; ++k) {
    if (k < 8u) {
      uint64_t fromLeft = ((centre << k) & sgEveryRow(0xFFu << k)) | ((left >> (8u - k)) & sgEveryRow((1u << k) - 1u));
      uint64_t fromRight = ((centre >> k) & sgEveryRow(0xFFu >> k)) | ((right << (8u - k)) & sgEveryRow(~(0xFFu >> k)));
      m |= fromLeft | fromRight;
    } else {
      m |= left | right;
    }
  }
  return m;
}

// The marked chunks of the entry at `entry` inside the span (none outside it, so none outside the sheet).
uint64_t sgMarkedInSpan(ivec2 entry, ivec2 begin, ivec2 end) {
  uint64_t span = sgSpanMask(entry, begin, end);
  if (span == uint64_t(0)) return span;
  return remap[(uint(entry.y) << params.entriesPerSideLog2) | uint(entry.x)].occupancy & span;
}

void main() {
  uint ownedIndex = sgSpanEntry(64u);
  if (!sgInSpan(ownedIndex)) return;
  SgOwnedEntry owned = ownedEntries[ownedIndex];
  uint radius = owned.instanceId < params.objectCount ? min(objects[owned.instanceId].supportChunks, SG_MAX_SUPPORT_CHUNKS) : 0u;
  uint64_t mask = uint64_t(0);
  if (radius > 0u) {
    SgShadelInstance instance = shadelInstances[owned.instanceId];
    if (owned.level < instance.levelCount) {
      SgLevelRect rect = levelRects[sgLevelRectIndex(instance, owned.level)];
      // Chunks overlapping [origin, origin + size): partly covered ones count.
      ivec2 begin = ivec2(rect.origin >> SG_CHUNK_SIZE_LOG2);
      ivec2 end = ivec2((rect.origin + rect.size + (SG_CHUNK_SIZE - 1u)) >> SG_CHUNK_SIZE_LOG2);
      uint side = 1u << params.entriesPerSideLog2;
      ivec2 e = ivec2(owned.entryIndex & (side - 1u), owned.entryIndex >> params.entriesPerSideLog2);
      uint64_t left = sgDilateRows(sgMarkedInSpan(e + ivec2(-1, -1), begin, end), sgMarkedInSpan(e + ivec2(-1, 0), begin, end),
                                   sgMarkedInSpan(e + ivec2(-1, 1), begin, end), radius);
      uint64_t centre = sgDilateRows(sgMarkedInSpan(e + ivec2(0, -1), begin, end), sgMarkedInSpan(e, begin, end),
                                     sgMarkedInSpan(e + ivec2(0, 1), begin, end), radius);
      uint64_t right = sgDilateRows(sgMarkedInSpan(e + ivec2(1, -1), begin, end), sgMarkedInSpan(e + ivec2(1, 0), begin, end),
                                    sgMarkedInSpan(e + ivec2(1, 1), begin, end), radius);
      // Its own marked chunks come back too: apply adds only the bits not yet set.
      mask = sgDilateColumns(left, centre, right, radius) & sgSpanMask(e, begin, end);
    }
  }
  // Written for every owned entry (0 without support): the buffer is transient, its contents undefined.
  supportMasks[ownedIndex] = mask;
}
#else
layout(local_size_x = 64) in;

void main() {
  uint ownedIndex = sgSpanEntry(64u);
  if (!sgInSpan(ownedIndex)) return;
  uint entry = ownedEntries[ownedIndex].entryIndex;
  uint64_t occupancy = remap[entry].occupancy;
  uint64_t added = supportMasks[ownedIndex] & ~occupancy;
  if (added == uint64_t(0)) return;
  remap[entry].occupancy = occupancy | added;
  uvec2 halves = unpackUint2x32(added);
  atomicAdd(counters.supportChunks, uint(bitCount(halves.x) + bitCount(halves.y)));
}
#endif
