#include <shadelgraph/gpu/graph_to_vulkan.hpp>

#include <utility>

namespace sg::gpu {
namespace {

// Ors together the Vulkan bits of every graph bit set in `flags`.
template <class E, class V, size_t N>
V mapBits(E flags, const std::pair<E, V> (&table)[N]) {
  V out = 0;
  for (const auto& [bit, vk] : table)
    if (graph::any(flags & bit)) out |= vk;
  return out;
}

}  // namespace

VkFormat toVk(graph::Format f) {
  using F = graph::Format;
  switch (f) {
    case F::Undefined: return VK_FORMAT_UNDEFINED;
    case F::R8Unorm: return VK_FORMAT_R8_UNORM;
    case F::RGBA8Unorm: return VK_FORMAT_R8G8B8A8_UNORM;
    case F::RGBA8Srgb: return VK_FORMAT_R8G8B8A8_SRGB;
    case F::BGRA8Unorm: return VK_FORMAT_B8G8R8A8_UNORM;
    case F::R16F: return VK_FORMAT_R16_SFLOAT;
    case F::RG16F: return VK_FORMAT_R16G16_SFLOAT;
    case F::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case F::R32F: return VK_FORMAT_R32_SFLOAT;
    case F::RG32F: return VK_FORMAT_R32G32_SFLOAT;
    case F::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
    case F::R32Uint: return VK_FORMAT_R32_UINT;
    case F::RG32Uint: return VK_FORMAT_R32G32_UINT;
    case F::RGBA32Uint: return VK_FORMAT_R32G32B32A32_UINT;
    case F::D32F: return VK_FORMAT_D32_SFLOAT;
    case F::D24S8: return VK_FORMAT_D24_UNORM_S8_UINT;
  }
  return VK_FORMAT_UNDEFINED;
}

VkPipelineStageFlags2 toVk(graph::PipelineStage stages) {
  using S = graph::PipelineStage;
  static const std::pair<S, VkPipelineStageFlags2> table[] = {
      {S::DrawIndirect, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT},
      {S::VertexInput, VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT},
      {S::VertexShader, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT},
      {S::FragmentShader, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT},
      {S::EarlyFragmentTests, VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT},
      {S::LateFragmentTests, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT},
      {S::ColorAttachmentOutput, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT},
      {S::ComputeShader, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT},
      {S::Transfer, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT},
      {S::AllCommands, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT},
  };
  return mapBits(stages, table);
}

VkAccessFlags2 toVk(graph::AccessFlag access) {
  using A = graph::AccessFlag;
  static const std::pair<A, VkAccessFlags2> table[] = {
      {A::IndirectCommandRead, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT},
      {A::IndexRead, VK_ACCESS_2_INDEX_READ_BIT},
      {A::VertexAttributeRead, VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT},
      {A::UniformRead, VK_ACCESS_2_UNIFORM_READ_BIT},
      {A::ShaderSampledRead, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT},
      {A::ShaderStorageRead, VK_ACCESS_2_SHADER_STORAGE_READ_BIT},
      {A::ShaderStorageWrite, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
      {A::ColorAttachmentRead, VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT},
      {A::ColorAttachmentWrite, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT},
      {A::DepthStencilRead, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT},
      {A::DepthStencilWrite, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT},
      {A::TransferRead, VK_ACCESS_2_TRANSFER_READ_BIT},
      {A::TransferWrite, VK_ACCESS_2_TRANSFER_WRITE_BIT},
  };
  return mapBits(access, table);
}

VkImageLayout toVk(graph::Layout layout) {
  using L = graph::Layout;
  switch (layout) {
    case L::Undefined: return VK_IMAGE_LAYOUT_UNDEFINED;
    case L::General: return VK_IMAGE_LAYOUT_GENERAL;
    case L::ColorAttachment: return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    case L::DepthAttachment: return VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    case L::DepthReadOnly: return VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL;
    case L::ShaderReadOnly: return VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    case L::TransferSrc: return VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    case L::TransferDst: return VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    case L::PresentSrc: return VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  }
  return VK_IMAGE_LAYOUT_UNDEFINED;
}

VkImageUsageFlags toVk(graph::ImageUsage usage) {
  using U = graph::ImageUsage;
  static const std::pair<U, VkImageUsageFlags> table[] = {
      {U::ColorAttachment, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT},
      {U::DepthAttachment, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT},
      {U::Sampled, VK_IMAGE_USAGE_SAMPLED_BIT},
      {U::Storage, VK_IMAGE_USAGE_STORAGE_BIT},
      {U::TransferSrc, VK_IMAGE_USAGE_TRANSFER_SRC_BIT},
      {U::TransferDst, VK_IMAGE_USAGE_TRANSFER_DST_BIT},
  };
  return mapBits(usage, table);
}

VkBufferUsageFlags toVk(graph::BufferUsage usage) {
  using U = graph::BufferUsage;
  static const std::pair<U, VkBufferUsageFlags> table[] = {
      {U::Storage, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT},   {U::Uniform, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT},
      {U::Vertex, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT},     {U::Index, VK_BUFFER_USAGE_INDEX_BUFFER_BIT},
      {U::Indirect, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT}, {U::TransferSrc, VK_BUFFER_USAGE_TRANSFER_SRC_BIT},
      {U::TransferDst, VK_BUFFER_USAGE_TRANSFER_DST_BIT}, {U::UniformTexel, VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT},
  };
  return mapBits(usage, table);
}

}  // namespace sg::gpu
