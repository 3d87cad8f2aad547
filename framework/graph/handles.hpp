#pragma once

#include <compare>
#include <cstdint>

namespace sg::graph {

inline constexpr uint32_t kInvalidIndex = ~uint32_t{0};

// Index of a declared resource; also its index in CompiledPlan::resources.
struct ResourceId {
  uint32_t index = kInvalidIndex;
  constexpr bool valid() const { return index != kInvalidIndex; }
  friend constexpr auto operator<=>(ResourceId, ResourceId) = default;
};

// Index of a declared pass, in declaration order; also its index in CompiledPlan::passes.
struct PassId {
  uint32_t index = kInvalidIndex;
  constexpr bool valid() const { return index != kInvalidIndex; }
  friend constexpr auto operator<=>(PassId, PassId) = default;
};

// One version of a resource. Version 0 is the content at frame start (undefined
// for transients); a pass writing version v produces version v + 1. Reads name
// the version they need, which is how passes declared in any order get ordered.
struct ResourceHandle {
  ResourceId id;
  uint32_t version = 0;
  constexpr bool valid() const { return id.valid(); }
  friend constexpr auto operator<=>(ResourceHandle, ResourceHandle) = default;
};

}  // namespace sg::graph
