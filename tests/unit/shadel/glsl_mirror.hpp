#pragma once
// The GLSL twins of the addressing and level-selection functions, run on
// many cases in one compute dispatch, against the C++ originals. Cases and
// results are flat uint arrays (floats by bit pattern) so no std430 layout
// question can hide a mismatch.
#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/shadel/level_selection.hpp>

namespace sg::shadel::test {

inline constexpr uint32_t kCaseWords = 20;
inline constexpr uint32_t kResultWords = 28;

inline const char* kMirrorShaderPath = "tests/shadel/glsl_mirror.comp";

inline const char* kMirrorShader = R"(#version 460
#extension GL_EXT_shader_atomic_int64 : require
#include "framework/shadel/shaders/shadel_level.glsl"
layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Cases { uint cases[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Results { uint results[]; };
layout(push_constant) uniform Push { uint count; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= count) return;
  uint c = i * 20u, r = i * 28u;
  uint log2 = cases[c + 2u];
  SgShadelAddress address = sgShadelAddress(uvec2(cases[c], cases[c + 1u]), log2);
  results[r + 0u] = address.entryIndex;
  results[r + 1u] = address.chunkIndex;
  results[r + 2u] = address.texelIndex;
  uvec2 back = sgVirtualShadel(address, log2);
  results[r + 3u] = back.x;
  results[r + 4u] = back.y;

  uint64_t occupancy = packUint2x32(uvec2(cases[c + 4u], cases[c + 5u]));
  uint chunk = cases[c + 3u];
  results[r + 5u] = sgChunksBefore(occupancy, chunk);
  results[r + 6u] = sgIsChunkMarked(occupancy, chunk) ? 1u : 0u;
  SgRemapEntry entry = SgRemapEntry(cases[c + 6u], 7u, occupancy);
  results[r + 7u] = sgPhysicalChunk(entry, chunk);
  uvec2 texel = sgStorageTexel(cases[c + 7u], cases[c + 8u], cases[c + 9u]);
  results[r + 8u] = texel.x;
  results[r + 9u] = texel.y;
  results[r + 10u] = sgStorageCounter(address.entryIndex, cases[c + 10u]);

  vec2 dx = uintBitsToFloat(uvec2(cases[c + 11u], cases[c + 12u]));
  vec2 dy = uintBitsToFloat(uvec2(cases[c + 13u], cases[c + 14u]));
  SgLevelSelection selection = sgSelectDetailLevel(dx, dy, uintBitsToFloat(cases[c + 15u]), cases[c + 16u]);
  results[r + 11u] = floatBitsToUint(selection.level);
  results[r + 12u] = selection.fine;
  results[r + 13u] = selection.coarse;
  results[r + 14u] = floatBitsToUint(selection.blend);
  results[r + 26u] = sgSelectFilterLevel(SG_FILTER_BILINEAR, dx, dy, uintBitsToFloat(cases[c + 15u]), cases[c + 16u]).fine;

  SgBilinearTaps taps = sgBilinearTaps(uintBitsToFloat(uvec2(cases[c + 17u], cases[c + 18u])), cases[c + 19u]);
  SgLevelRect rect = SgLevelRect(uvec2(1000u, 2000u), cases[c + 19u], 64u);
  uvec2 corner = sgFootprintShadel(rect, taps, 3u);  // (hi.x, hi.y) + origin
  results[r + 15u] = taps.lo.x;
  results[r + 16u] = taps.lo.y;
  results[r + 17u] = corner.x - 1000u;
  results[r + 18u] = corner.y - 2000u;
  results[r + 19u] = floatBitsToUint(taps.weight.x);
  results[r + 20u] = floatBitsToUint(taps.weight.y);
  uvec2 nearest = sgNearestTap(taps);
  results[r + 21u] = nearest.x;
  results[r + 22u] = nearest.y;

  // The tile texel (cases 3, 8 mod 9: gutter included) of physical chunk case 7.
  uvec2 stored = sgStoredTexel(cases[c + 7u], uvec2(cases[c + 3u] % 9u, cases[c + 8u] % 9u), cases[c + 9u]);
  results[r + 23u] = stored.x;
  results[r + 24u] = stored.y;
  uvec2 tile = sgFootprintTileShadel(rect, taps);
  results[r + 25u] = (tile.x - 1000u) | ((tile.y - 2000u) << 16u);
}
)";

// Random cases: shadels across sheets of 64K..512K, occupancy patterns,
// derivatives over 12 octaves, UVs slightly past [0,1].
std::vector<uint32_t> makeMirrorCases(uint32_t count, uint32_t seed);

// Compares GPU results with the C++ functions; returns a description of the
// first mismatch, or an empty string. Level selections within 1e-4 of an
// integer level are compared only loosely (log2 may differ in the last ulp).
// rule: the level rule the shader was compiled with (levelRuleDefines, the
// pipeline variant of shadel-mark and composite); {} without it.
std::string compareMirrorResults(const std::vector<uint32_t>& cases, const uint32_t* results, uint32_t count,
                                 LevelRule rule = {});

}  // namespace sg::shadel::test
