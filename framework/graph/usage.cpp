#include <shadelgraph/graph/usage.hpp>

#include <shadelgraph/graph/flag_names.hpp>

#include <array>

namespace sg::graph {

std::string toString(ImageUsage usage) {
  using U = ImageUsage;
  static constexpr std::array<std::pair<U, std::string_view>, 6> kNames{{
      {U::ColorAttachment, "ColorAttachment"},
      {U::DepthAttachment, "DepthAttachment"},
      {U::Sampled, "Sampled"},
      {U::Storage, "Storage"},
      {U::TransferSrc, "TransferSrc"},
      {U::TransferDst, "TransferDst"},
  }};
  return detail::joinFlagNames(usage, kNames);
}

std::string toString(BufferUsage usage) {
  using U = BufferUsage;
  static constexpr std::array<std::pair<U, std::string_view>, 8> kNames{{
      {U::Storage, "Storage"},
      {U::Uniform, "Uniform"},
      {U::Vertex, "Vertex"},
      {U::Index, "Index"},
      {U::Indirect, "Indirect"},
      {U::TransferSrc, "TransferSrc"},
      {U::TransferDst, "TransferDst"},
      {U::UniformTexel, "UniformTexel"},
  }};
  return detail::joinFlagNames(usage, kNames);
}

}  // namespace sg::graph
