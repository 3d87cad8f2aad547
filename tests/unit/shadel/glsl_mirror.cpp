#include "glsl_mirror.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <string>

#include <shadelgraph/shadel/level_selection.hpp>
#include <shadelgraph/shadel/shadel_address.hpp>

namespace sg::shadel::test {
namespace {

uint32_t bits(float f) { return std::bit_cast<uint32_t>(f); }
float value(uint32_t u) { return std::bit_cast<float>(u); }

}  // namespace

std::vector<uint32_t> makeMirrorCases(uint32_t count, uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<uint32_t> cases;
  cases.reserve(size_t{count} * kCaseWords);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t sheetLog2 = 16 + static_cast<uint32_t>(rng() % 4);
    const uint32_t size = 1u << sheetLog2;
    uint64_t occupancy = rng();
    if (i % 5 == 0) occupancy &= rng() & rng();
    if (i % 17 == 0) occupancy = ~uint64_t{0};
    if (i % 19 == 0) occupancy = 0;
    const float length = std::exp2(unit(rng) * 14.0f - 2.0f), angle = unit(rng) * 6.2831853f;
    const glm::vec2 dx = length * glm::vec2(std::cos(angle), std::sin(angle));
    const glm::vec2 dy = (0.2f + unit(rng)) * length * glm::vec2(-std::sin(angle), std::cos(angle));
    const uint32_t levelSize = 8u << (rng() % 10);
    const uint32_t words[kCaseWords] = {
        static_cast<uint32_t>(rng() % size), static_cast<uint32_t>(rng() % size), sheetLog2 - 6,
        static_cast<uint32_t>(rng() % 64), static_cast<uint32_t>(occupancy), static_cast<uint32_t>(occupancy >> 32),
        i % 13 == 0 ? kNoStorage : static_cast<uint32_t>(rng() % 1000000), static_cast<uint32_t>(rng() % 500000),
        static_cast<uint32_t>(rng() % 64), 1u + static_cast<uint32_t>(rng() % 2048), 1u + static_cast<uint32_t>(rng() % 32),
        bits(dx.x), bits(dx.y), bits(dy.x), bits(dy.y), bits(unit(rng) * 2.0f - 0.5f), 1u + static_cast<uint32_t>(rng() % 12),
        bits(unit(rng) * 1.04f - 0.02f), bits(unit(rng) * 1.04f - 0.02f), levelSize};
    cases.insert(cases.end(), words, words + kCaseWords);
  }
  return cases;
}

std::string compareMirrorResults(const std::vector<uint32_t>& cases, const uint32_t* results, uint32_t count,
                                 LevelRule rule) {
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t* c = cases.data() + size_t{i} * kCaseWords;
    const uint32_t* r = results + size_t{i} * kResultWords;
    const auto fail = [&](const std::string& what, double gpu, double cpu) {
      return "case " + std::to_string(i) + ": " + what + " GLSL " + std::to_string(gpu) + " C++ " + std::to_string(cpu);
    };
    const ShadelAddress address = addressOf({c[0], c[1]}, c[2]);
    const glm::uvec2 back = virtualShadelOf(address, c[2]);
    const uint64_t occupancy = c[4] | (uint64_t{c[5]} << 32);
    RemapEntry entry;
    entry.storageBase = c[6];
    entry.occupancy = occupancy;
    const glm::uvec2 texel = storageTexel(c[7], c[8], c[9]);
    const uint32_t expected[] = {address.entryIndex, address.chunkIndex, address.texelIndex, back.x, back.y,
                                 chunksBefore(occupancy, c[3]), isChunkMarked(occupancy, c[3]) ? 1u : 0u,
                                 physicalChunk(entry, c[3]), texel.x, texel.y, storageCounterFor(address.entryIndex, c[10])};
    static const char* names[] = {"entryIndex", "chunkIndex", "texelIndex", "virtualShadel.x", "virtualShadel.y",
                                  "chunksBefore", "isChunkMarked", "physicalChunk", "storageTexel.x", "storageTexel.y",
                                  "storageCounter"};
    for (size_t k = 0; k < std::size(expected); ++k)
      if (r[k] != expected[k]) return fail(names[k], r[k], expected[k]);

    const LevelSelection selection = selectDetailLevel({value(c[11]), value(c[12])}, {value(c[13]), value(c[14])},
                                                       value(c[15]) + rule.bias, c[16], rule.maxAnisotropyLog2);
    if (std::abs(value(r[11]) - selection.level) > 1e-5f * std::max(1.0f, std::abs(selection.level)))
      return fail("level", value(r[11]), selection.level);
    const bool nearBoundary = std::abs(selection.level - std::round(selection.level)) < 1e-4f;
    if (!nearBoundary) {
      if (r[12] != selection.fine) return fail("fine", r[12], selection.fine);
      if (r[13] != selection.coarse) return fail("coarse", r[13], selection.coarse);
      if (std::abs(value(r[14]) - selection.blend) > 1e-5f) return fail("blend", value(r[14]), selection.blend);
    }
    // The nearest level's boundaries are the half levels.
    const LevelSelection nearestLevel =
        selectFilterLevel(CompositeFilter::Bilinear, {value(c[11]), value(c[12])}, {value(c[13]), value(c[14])},
                          value(c[15]) + rule.bias, c[16], rule.maxAnisotropyLog2);
    const bool nearHalf = std::abs(selection.level - 0.5f - std::round(selection.level - 0.5f)) < 1e-4f;
    if (!nearHalf && r[26] != nearestLevel.fine) return fail("nearest level", r[26], nearestLevel.fine);

    const BilinearTaps taps = bilinearTaps({value(c[17]), value(c[18])}, c[19]);
    const uint32_t tapWords[] = {taps.lo.x, taps.lo.y, taps.hi.x, taps.hi.y, bits(taps.weight.x), bits(taps.weight.y)};
    static const char* tapNames[] = {"taps.lo.x", "taps.lo.y", "taps.hi.x", "taps.hi.y", "taps.weight.x", "taps.weight.y"};
    for (size_t k = 0; k < 6; ++k)
      if (r[15 + k] != tapWords[k]) return fail(tapNames[k], r[15 + k], tapWords[k]);
    const glm::uvec2 nearest = nearestTap(taps);
    if (r[21] != nearest.x || r[22] != nearest.y) return fail("nearestTap", r[21] * 1e6 + r[22], nearest.x * 1e6 + nearest.y);

    const glm::uvec2 stored = storedTexel(c[7], {c[3] % 9, c[8] % 9}, c[9]);
    if (r[23] != stored.x || r[24] != stored.y) return fail("storedTexel", r[23] * 1e6 + r[24], stored.x * 1e6 + stored.y);
    // FilterFootprint::tiles: the level's top-left tap, level-local here.
    if (r[25] != (taps.lo.x | (taps.lo.y << 16))) return fail("footprint tile", r[25], taps.lo.x | (taps.lo.y << 16));
  }
  return {};
}

}  // namespace sg::shadel::test
