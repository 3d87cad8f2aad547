#include <shadelgraph/graph/format.hpp>

namespace sg::graph {

uint32_t bytesPerTexel(Format format) {
  switch (format) {
    case Format::Undefined: return 0;
    case Format::R8Unorm: return 1;
    case Format::R16F: return 2;
    case Format::RGBA8Unorm:
    case Format::RGBA8Srgb:
    case Format::BGRA8Unorm:
    case Format::RG16F:
    case Format::R32F:
    case Format::R32Uint:
    case Format::D32F:
    case Format::D24S8: return 4;
    case Format::RGBA16F:
    case Format::RG32F:
    case Format::RG32Uint: return 8;
    case Format::RGBA32F:
    case Format::RGBA32Uint: return 16;
  }
  return 0;
}

std::string_view toString(Format format) {
  switch (format) {
    case Format::Undefined: return "Undefined";
    case Format::R8Unorm: return "R8Unorm";
    case Format::RGBA8Unorm: return "RGBA8Unorm";
    case Format::RGBA8Srgb: return "RGBA8Srgb";
    case Format::BGRA8Unorm: return "BGRA8Unorm";
    case Format::R16F: return "R16F";
    case Format::RG16F: return "RG16F";
    case Format::RGBA16F: return "RGBA16F";
    case Format::R32F: return "R32F";
    case Format::RG32F: return "RG32F";
    case Format::RGBA32F: return "RGBA32F";
    case Format::R32Uint: return "R32Uint";
    case Format::RG32Uint: return "RG32Uint";
    case Format::RGBA32Uint: return "RGBA32Uint";
    case Format::D32F: return "D32F";
    case Format::D24S8: return "D24S8";
  }
  return "?";
}

}  // namespace sg::graph
