#include <shadelgraph/scene/instance.hpp>

namespace sg::scene {

std::optional<ShadingMode> parseShadingMode(std::string_view text) {
  if (text == "auto") return ShadingMode::Auto;
  if (text == "decoupled") return ShadingMode::Decoupled;
  if (text == "forward") return ShadingMode::Forward;
  return std::nullopt;
}

std::string_view toString(ShadingMode mode) {
  switch (mode) {
    case ShadingMode::Auto: return "auto";
    case ShadingMode::Decoupled: return "decoupled";
    case ShadingMode::Forward: return "forward";
  }
  return "auto";
}

}  // namespace sg::scene
