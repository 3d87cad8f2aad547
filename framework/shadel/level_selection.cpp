#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/packing.hpp>

#include <shadelgraph/shadel/level_selection.hpp>
#include <shadelgraph/shadel/remap_entry.hpp>
#include <shadelgraph/shadel/shadel_address.hpp>

namespace sg::shadel {
namespace {

// Keeps log2 finite for zero derivatives (a pixel whose UVs do not change,
// e.g. on a zero-UV-area triangle): level -33, clamped to 0.
constexpr float kMinFootprintSquared = 1e-20f;

}  // namespace

uint32_t packLevelRule(LevelRule rule) { return glm::packHalf2x16({rule.maxAnisotropyLog2, rule.bias}); }

LevelRule unpackLevelRule(uint32_t packed) {
  const glm::vec2 v = glm::unpackHalf2x16(packed);
  return {.maxAnisotropyLog2 = v.x, .bias = v.y};
}

std::vector<std::pair<std::string, std::string>> levelRuleDefines(LevelRule rule) {
  if (rule.maxAnisotropyLog2 == 0.0f && rule.bias == 0.0f) return {};
  // %.9e: a float literal (with a point) that reads back as the same float.
  const auto literal = [](float f) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9e", double(f));
    return std::string(text);
  };
  return {{"SG_LEVEL_RULE_ANISOTROPY_LOG2", literal(rule.maxAnisotropyLog2)}, {"SG_LEVEL_RULE_BIAS", literal(rule.bias)}};
}

float levelFootprintSquared(glm::vec2 dShadelDx, glm::vec2 dShadelDy, float maxAnisotropyLog2) {
  const float longer = std::max(glm::dot(dShadelDx, dShadelDx), glm::dot(dShadelDy, dShadelDy));
  if (!(maxAnisotropyLog2 > 0.0f)) return longer;
  const float det = dShadelDx.x * dShadelDy.y - dShadelDx.y * dShadelDy.x;
  const float minor = longer > 0.0f ? det * det / longer : 0.0f;
  return std::max(longer * std::exp2(-2.0f * maxAnisotropyLog2), minor);
}

LevelSelection selectDetailLevel(glm::vec2 dShadelDx, glm::vec2 dShadelDy, float bias, uint32_t levelCount,
                                 float maxAnisotropyLog2) {
  const float rhoSquared = levelFootprintSquared(dShadelDx, dShadelDy, maxAnisotropyLog2);
  LevelSelection selection;
  selection.level = 0.5f * std::log2(std::max(rhoSquared, kMinFootprintSquared)) + bias;
  float clamped = selection.level;
  if (!(clamped >= 0.0f)) clamped = 0.0f;  // also catches NaN
  clamped = std::min(clamped, static_cast<float>(levelCount - 1));
  selection.fine = static_cast<uint32_t>(std::floor(clamped));
  selection.coarse = std::min(selection.fine + 1, levelCount - 1);
  selection.blend = selection.coarse == selection.fine ? 0.0f : clamped - static_cast<float>(selection.fine);
  return selection;
}

LevelSelection selectFilterLevel(CompositeFilter filter, glm::vec2 dShadelDx, glm::vec2 dShadelDy, float bias,
                                 uint32_t levelCount, float maxAnisotropyLog2) {
  LevelSelection selection = selectDetailLevel(dShadelDx, dShadelDy, bias, levelCount, maxAnisotropyLog2);
  if (filter == CompositeFilter::Trilinear) return selection;
  // fine + blend is the clamped level; rounding it cannot pass levelCount - 1.
  selection.fine = selection.blend >= 0.5f ? selection.coarse : selection.fine;
  selection.coarse = selection.fine;
  selection.blend = 0.0f;
  return selection;
}

BilinearTaps bilinearTaps(glm::vec2 uv, uint32_t levelSize) {
  const float size = static_cast<float>(levelSize);
  const glm::vec2 p = glm::clamp(uv * size - 0.5f, glm::vec2(0.0f), glm::vec2(size - 1.0f));
  const glm::vec2 base = glm::floor(p);
  BilinearTaps taps;
  taps.lo = glm::uvec2(base);
  taps.hi = glm::min(taps.lo + 1u, glm::uvec2(levelSize - 1));
  taps.weight = p - base;
  return taps;
}

TrilinearFootprint trilinearFootprint(glm::vec2 uv, const LevelSelection& selection, std::span<const LevelRect> levels) {
  TrilinearFootprint footprint;
  footprint.selection = selection;
  const uint32_t chosen[2] = {selection.fine, selection.coarse};
  for (uint32_t i = 0; i < 2; ++i) {
    const LevelRect& rect = levels[chosen[i]];
    const BilinearTaps taps = bilinearTaps(uv, rect.size);
    (i == 0 ? footprint.fineWeight : footprint.coarseWeight) = taps.weight;
    footprint.shadels[i * 4 + 0] = rect.origin + glm::uvec2(taps.lo.x, taps.lo.y);
    footprint.shadels[i * 4 + 1] = rect.origin + glm::uvec2(taps.hi.x, taps.lo.y);
    footprint.shadels[i * 4 + 2] = rect.origin + glm::uvec2(taps.lo.x, taps.hi.y);
    footprint.shadels[i * 4 + 3] = rect.origin + glm::uvec2(taps.hi.x, taps.hi.y);
  }
  return footprint;
}

glm::uvec2 nearestTap(const BilinearTaps& taps) {
  return {taps.weight.x >= 0.5f ? taps.hi.x : taps.lo.x, taps.weight.y >= 0.5f ? taps.hi.y : taps.lo.y};
}

FilterFootprint filterFootprint(CompositeFilter filter, glm::vec2 uv, const LevelSelection& selection,
                                std::span<const LevelRect> levels) {
  FilterFootprint footprint;
  const bool twoLevels = filter == CompositeFilter::Trilinear && selection.coarse != selection.fine;
  for (uint32_t level : {selection.fine, selection.coarse}) {
    if (footprint.tileCount == (twoLevels ? 2u : 1u)) break;
    const LevelRect& rect = levels[level];
    const BilinearTaps taps = bilinearTaps(uv, rect.size);
    footprint.tiles[footprint.tileCount++] = rect.origin + taps.lo;
  }
  if (filter == CompositeFilter::Point) {
    const LevelRect& rect = levels[selection.fine];
    footprint.shadels[footprint.count++] = rect.origin + nearestTap(bilinearTaps(uv, rect.size));
    return footprint;
  }
  const TrilinearFootprint trilinear = trilinearFootprint(uv, selection, levels);
  footprint.count = twoLevels ? 8 : 4;
  for (uint32_t i = 0; i < footprint.count; ++i) footprint.shadels[i] = trilinear.shadels[i];
  return footprint;
}

bool inFootprintTile(glm::uvec2 tileShadel, glm::uvec2 shadel) {
  const glm::uvec2 chunkOrigin = tileShadel & ~(kChunkSize - 1);
  return glm::all(glm::greaterThanEqual(shadel, chunkOrigin)) &&
         glm::all(glm::lessThan(shadel, chunkOrigin + kStoredChunkSize));
}

}  // namespace sg::shadel
