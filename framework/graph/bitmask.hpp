#pragma once

#include <type_traits>

namespace sg::graph {

// Opt-in bitwise operators for flag enums: specialise EnableBitmask<E> to true.
// Scoped enums keep flag sets from different vocabularies from mixing.
template <class E>
struct EnableBitmask : std::false_type {};

template <class E>
concept BitmaskEnum = std::is_enum_v<E> && EnableBitmask<E>::value;

template <BitmaskEnum E>
constexpr E operator|(E a, E b) {
  using U = std::underlying_type_t<E>;
  return static_cast<E>(static_cast<U>(a) | static_cast<U>(b));
}

template <BitmaskEnum E>
constexpr E operator&(E a, E b) {
  using U = std::underlying_type_t<E>;
  return static_cast<E>(static_cast<U>(a) & static_cast<U>(b));
}

template <BitmaskEnum E>
constexpr E operator~(E a) {
  using U = std::underlying_type_t<E>;
  return static_cast<E>(~static_cast<U>(a));
}

template <BitmaskEnum E>
constexpr E& operator|=(E& a, E b) {
  return a = a | b;
}

template <BitmaskEnum E>
constexpr E& operator&=(E& a, E b) {
  return a = a & b;
}

// True if any bit is set.
template <BitmaskEnum E>
constexpr bool any(E a) {
  return static_cast<std::underlying_type_t<E>>(a) != 0;
}

// True if every bit of `part` is set in `whole`.
template <BitmaskEnum E>
constexpr bool contains(E whole, E part) {
  return (whole & part) == part;
}

}  // namespace sg::graph
