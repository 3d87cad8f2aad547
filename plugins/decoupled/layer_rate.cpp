#include "layer_rate.hpp"

#include <algorithm>

namespace sg::plugins {

uint32_t keptLayerBits(const plugin::Registry& registry, const plugin::MaterialStack& material,
                       std::span<const std::string> slots, const LayerKeepState& state) {
  if (!state.historyValid || state.materialChanged) return 0;
  uint32_t bits = 0;
  for (const auto& name : material.layers) {
    const plugin::MaterialLayer& layer = registry.layer(name);
    if (!layer.viewIndependent()) continue;
    if (layer.dependsOn == plugin::LayerDependence::World && state.moved) continue;
    // Refreshed on every M-th shade frame (all objects together; M = 1: every shade frame).
    if (state.shadeFrame && state.shadeFrameIndex % std::max(layer.refreshShadeFrames, 1u) == 0) continue;
    const auto slot = std::find(slots.begin(), slots.end(), name);
    if (slot != slots.end()) bits |= 1u << uint32_t(slot - slots.begin());
  }
  return bits;
}

}  // namespace sg::plugins
