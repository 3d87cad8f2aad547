#include <shadelgraph/graph/sync_types.hpp>

#include <shadelgraph/graph/flag_names.hpp>

#include <array>

namespace sg::graph {

std::string toString(PipelineStage stages) {
  using S = PipelineStage;
  static constexpr std::array<std::pair<S, std::string_view>, 10> kNames{{
      {S::DrawIndirect, "DrawIndirect"},
      {S::VertexInput, "VertexInput"},
      {S::VertexShader, "VertexShader"},
      {S::FragmentShader, "FragmentShader"},
      {S::EarlyFragmentTests, "EarlyFragmentTests"},
      {S::LateFragmentTests, "LateFragmentTests"},
      {S::ColorAttachmentOutput, "ColorAttachmentOutput"},
      {S::ComputeShader, "ComputeShader"},
      {S::Transfer, "Transfer"},
      {S::AllCommands, "AllCommands"},
  }};
  return detail::joinFlagNames(stages, kNames);
}

std::string toString(AccessFlag access) {
  using A = AccessFlag;
  static constexpr std::array<std::pair<A, std::string_view>, 13> kNames{{
      {A::IndirectCommandRead, "IndirectCommandRead"},
      {A::IndexRead, "IndexRead"},
      {A::VertexAttributeRead, "VertexAttributeRead"},
      {A::UniformRead, "UniformRead"},
      {A::ShaderSampledRead, "ShaderSampledRead"},
      {A::ShaderStorageRead, "ShaderStorageRead"},
      {A::ShaderStorageWrite, "ShaderStorageWrite"},
      {A::ColorAttachmentRead, "ColorAttachmentRead"},
      {A::ColorAttachmentWrite, "ColorAttachmentWrite"},
      {A::DepthStencilRead, "DepthStencilRead"},
      {A::DepthStencilWrite, "DepthStencilWrite"},
      {A::TransferRead, "TransferRead"},
      {A::TransferWrite, "TransferWrite"},
  }};
  return detail::joinFlagNames(access, kNames);
}

std::string_view toString(Layout layout) {
  switch (layout) {
    case Layout::Undefined: return "Undefined";
    case Layout::General: return "General";
    case Layout::ColorAttachment: return "ColorAttachment";
    case Layout::DepthAttachment: return "DepthAttachment";
    case Layout::DepthReadOnly: return "DepthReadOnly";
    case Layout::ShaderReadOnly: return "ShaderReadOnly";
    case Layout::TransferSrc: return "TransferSrc";
    case Layout::TransferDst: return "TransferDst";
    case Layout::PresentSrc: return "PresentSrc";
  }
  return "?";
}

}  // namespace sg::graph
