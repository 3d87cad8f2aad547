#pragma once
// Choices without a branch, for the compile steps' loops where a condition
// flips at random with the graph's data: a mispredicted branch costs more than
// the few instructions of a mask, and GCC turns a ?: into a jump when it likes.

#include <concepts>

namespace sg::graph {

// All ones if `condition`, else zero.
template <std::unsigned_integral T>
constexpr T maskIf(bool condition) {
  return static_cast<T>(T{0} - static_cast<T>(condition));
}

// `yes` where `mask` is set, else `no` (one mask made once, several choices).
template <std::unsigned_integral T>
constexpr T pick(T mask, T yes, T no) {
  return static_cast<T>(no ^ ((yes ^ no) & mask));
}

// `yes` if `condition`, else `no`.
template <std::unsigned_integral T>
constexpr T choose(bool condition, T yes, T no) {
  return pick(maskIf<T>(condition), yes, no);
}

}  // namespace sg::graph
