#pragma once
// Per-layer shade rate: which of an object's view-independent layers
// (MaterialLayer::dependsOn World or Surface) keep last frame's values this
// frame instead of being computed. View-dependent layers follow the shade
// frame; a kept layer is recomputed only when its inputs change (its object
// got another material or, for World layers, moved) or on every
// refreshShadeFrames-th shade frame. The result is the object record's
// keepLayers bits (bit = the layer's slot in the frame's kept layers).
#include <cstdint>
#include <span>
#include <string>

#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugins {

struct LayerKeepState {
  bool historyValid = false;    // last frame's layer images and remap describe this frame's storage
  bool materialChanged = false;  // allocated or given another material this frame
  bool moved = false;           // its transform changed this frame
  bool shadeFrame = false;
  uint64_t shadeFrameIndex = 0;  // 1 for the first shade frame, then 2, ...
};

// `slots`: the frame's layers with history (LayerPlan::persistent), index = bit.
uint32_t keptLayerBits(const plugin::Registry& registry, const plugin::MaterialStack& material,
                       std::span<const std::string> slots, const LayerKeepState& state);

}  // namespace sg::plugins
