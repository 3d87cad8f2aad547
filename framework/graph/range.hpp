#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace sg::graph {

// A slice of a flat array. Declarations and plans keep accesses, barriers,
// waits and aliases in one array each (few allocations, contiguous walks) and
// hand out spans of them.
struct Range {
  uint32_t first = 0;
  uint32_t count = 0;
  friend bool operator==(Range, Range) = default;
};

template <class T>
std::span<const T> slice(const std::vector<T>& all, Range range) {
  return {all.data() + range.first, range.count};
}

}  // namespace sg::graph
