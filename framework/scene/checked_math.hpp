#pragma once
// Internal to the loaders: byte arithmetic on sizes taken from a file, where
// every sum and product can overflow. One place, so no bounds check wraps.
#include <cstdint>
#include <optional>

namespace sg::scene::detail {

// a + b and a * b, or nullopt when the result does not fit 64 bits.
inline std::optional<uint64_t> checkedAdd(uint64_t a, uint64_t b) {
  uint64_t sum = 0;
  if (__builtin_add_overflow(a, b, &sum)) return std::nullopt;
  return sum;
}
inline std::optional<uint64_t> checkedMul(uint64_t a, uint64_t b) {
  uint64_t product = 0;
  if (__builtin_mul_overflow(a, b, &product)) return std::nullopt;
  return product;
}

// The end of `count` (>= 1) elements of `elementSize` bytes, `stride` apart,
// starting at `offset`: offset + (count - 1) * stride + elementSize.
inline std::optional<uint64_t> elementsEnd(uint64_t offset, uint64_t count, uint64_t elementSize, uint64_t stride) {
  if (count == 0) return offset;
  const std::optional<uint64_t> steps = checkedMul(count - 1, stride);
  if (!steps) return std::nullopt;
  const std::optional<uint64_t> start = checkedAdd(offset, *steps);
  return start ? checkedAdd(*start, elementSize) : std::nullopt;
}

// True when [offset, offset + length) lies inside `size` bytes.
inline bool fitsIn(uint64_t offset, uint64_t length, uint64_t size) { return offset <= size && length <= size - offset; }

}  // namespace sg::scene::detail
