#pragma once
// The decoupled package's names for the GPU records of the shared shader
// interface (framework/shadel/shaders/decoupled_interface.h).
#include <cstdint>

#include <shadelgraph/shadel/shaders/decoupled_interface.h>

namespace sg::plugins {

using shader::kMaxLevels;
using shader::kMaxPersistentLayers;
using shader::kStorageCounters;
using DecoupledObject = shader::SgDecoupledObject;
using ShadeCounters = shader::SgShadeCounters;
using DecoupledParams = shader::SgDecoupledParams;

// Shadels stored this frame (shaded or kept): the allocated chunks' shadels
// less those the shadel masks left unshaded (no pixel reads them).
constexpr uint64_t shadelsStored(const ShadeCounters& c) { return 64ull * c.chunksAllocated - c.shadelsSkipped; }
// Shadels the layers shaded this frame.
constexpr uint64_t shadelsShaded(const ShadeCounters& c) { return 64ull * c.chunksShaded - c.shadelsSkipped; }
// Shadels stored per covered pixel (0 without covered pixels).
constexpr double shadelsPerCoveredPixel(const ShadeCounters& c) {
  return c.coveredPixels ? double(shadelsStored(c)) / c.coveredPixels : 0.0;
}

constexpr uint64_t workBufferBytes(uint32_t objects, uint32_t items) {
  return 4ull * (uint64_t{shader::kWorkSlotsPerObject} * objects + shader::kWorkGlobalSlots +
                 uint64_t{shader::kWorkSlotsPerItem} * items);
}

}  // namespace sg::plugins
