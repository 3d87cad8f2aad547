#pragma once

// Internal: formats a flag set as "A|B|C" ("None" when empty).

#include <shadelgraph/graph/bitmask.hpp>

#include <array>
#include <string>
#include <string_view>
#include <utility>

namespace sg::graph::detail {

template <BitmaskEnum E, std::size_t N>
std::string joinFlagNames(E flags, const std::array<std::pair<E, std::string_view>, N>& names) {
  if (!any(flags)) return "None";
  std::string out;
  for (const auto& [bit, name] : names) {
    if (!any(flags & bit)) continue;
    if (!out.empty()) out += '|';
    out += name;
  }
  return out;
}

}  // namespace sg::graph::detail
