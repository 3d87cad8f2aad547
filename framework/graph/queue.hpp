#pragma once

#include <shadelgraph/graph/bitmask.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace sg::graph {

// Logical queues. Each has its own timeline semaphore; the gpu layer maps them
// onto whatever physical queues exist (on lavapipe all three share one).
enum class QueueClass : uint8_t {
  Graphics,
  AsyncCompute,
  Transfer,
};
inline constexpr uint32_t kQueueClassCount = 3;

// What a pass records: it sets the default shader stage of its accesses and
// which accesses are legal. A compute pass may run on the graphics queue.
enum class PassKind : uint8_t {
  Raster,
  Compute,
  Transfer,
};

enum class QueueMask : uint8_t {
  None = 0,
  Graphics = 1u << 0,
  AsyncCompute = 1u << 1,
  Transfer = 1u << 2,
};
template <>
struct EnableBitmask<QueueMask> : std::true_type {};

constexpr QueueMask toMask(QueueClass queue) { return static_cast<QueueMask>(1u << static_cast<uint32_t>(queue)); }
constexpr uint32_t queueIndex(QueueClass queue) { return static_cast<uint32_t>(queue); }
// Number of distinct queues in the mask.
constexpr uint32_t queueCount(QueueMask mask) {
  const auto bits = static_cast<uint32_t>(mask);
  return (bits & 1u) + ((bits >> 1) & 1u) + ((bits >> 2) & 1u);
}
// The pass kind a queue implies when addPass() is not told one.
PassKind defaultPassKind(QueueClass queue);
// Inline: validate() asks it for every pass.
constexpr bool canRunOn(PassKind kind, QueueClass queue) {
  switch (kind) {
    case PassKind::Raster: return queue == QueueClass::Graphics;
    case PassKind::Compute: return queue != QueueClass::Transfer;
    case PassKind::Transfer: return true;
  }
  return false;
}

std::string_view toString(QueueClass queue);
std::string_view toString(PassKind kind);
std::string toString(QueueMask mask);

}  // namespace sg::graph
