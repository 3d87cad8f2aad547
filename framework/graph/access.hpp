#pragma once

#include <shadelgraph/graph/bitmask.hpp>
#include <shadelgraph/graph/queue.hpp>
#include <shadelgraph/graph/sync_types.hpp>
#include <shadelgraph/graph/usage.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sg::graph {

// How a pass uses a resource. Writes: ColorAttachment, DepthAttachment,
// StorageWrite, StorageReadWrite, TransferDst; everything else reads.
enum class Access : uint8_t {
  ColorAttachment,      // write (clear or overwrite); add ColorAttachmentRead to load or blend
  ColorAttachmentRead,  // load / blend of the attachment's previous content
  DepthAttachment,      // depth test and write
  DepthRead,            // read-only depth test
  Sampled,
  StorageRead,
  StorageWrite,
  StorageReadWrite,
  IndirectArgs,
  Vertex,
  Index,
  Uniform,
  TransferSrc,
  TransferDst,
  Present,  // read by the presentation engine: layout PresentSrc, no pipeline stage
};

// Shader stages of a Sampled / Storage* / Uniform access. None means "the
// pass kind's default": Fragment for raster passes, Compute for compute passes.
enum class ShaderStage : uint8_t {
  None = 0,
  Vertex = 1u << 0,
  Fragment = 1u << 1,
  Compute = 1u << 2,
};
template <>
struct EnableBitmask<ShaderStage> : std::true_type {};

// The synchronization scope of one access.
struct AccessSync {
  PipelineStage stages = PipelineStage::None;
  AccessFlag access = AccessFlag::None;
  Layout layout = Layout::Undefined;  // meaningless for buffers
};

namespace detail {

// Everything the graph knows about an Access, one row per enumerator (the
// compile steps look these up per access, so they are inline table reads).
struct AccessTraits {
  std::string_view name;
  bool write;
  bool shader;      // performed by shaders: its stages come from ShaderStage
  bool imageOnly;
  bool bufferOnly;
  bool inCompute;   // legal in a compute pass
  bool inTransfer;  // legal in a transfer pass
  PipelineStage stages;  // for non-shader accesses
  AccessFlag access;
  Layout layout;
  ImageUsage imageUsage;
  BufferUsage bufferUsage;
};

using S = PipelineStage;
using A = AccessFlag;
using L = Layout;
using IU = ImageUsage;
using BU = BufferUsage;
inline constexpr S kDepthTests = S::EarlyFragmentTests | S::LateFragmentTests;

inline constexpr std::array<AccessTraits, 15> kAccessTraits{{
    // name                 write  shader image  buffer compute transfer stages  access  layout  usages
    {"ColorAttachment", true, false, true, false, false, false, S::ColorAttachmentOutput, A::ColorAttachmentWrite,
     L::ColorAttachment, IU::ColorAttachment, BU::None},
    {"ColorAttachmentRead", false, false, true, false, false, false, S::ColorAttachmentOutput,
     A::ColorAttachmentRead, L::ColorAttachment, IU::ColorAttachment, BU::None},
    // The depth test reads what it writes.
    {"DepthAttachment", true, false, true, false, false, false, kDepthTests,
     A::DepthStencilRead | A::DepthStencilWrite, L::DepthAttachment, IU::DepthAttachment, BU::None},
    {"DepthRead", false, false, true, false, false, false, kDepthTests, A::DepthStencilRead, L::DepthReadOnly,
     IU::DepthAttachment, BU::None},
    // Of a buffer: a uniform texel buffer (samplerBuffer).
    {"Sampled", false, true, false, false, true, false, S::None, A::ShaderSampledRead, L::ShaderReadOnly, IU::Sampled,
     BU::UniformTexel},
    {"StorageRead", false, true, false, false, true, false, S::None, A::ShaderStorageRead, L::General, IU::Storage,
     BU::Storage},
    {"StorageWrite", true, true, false, false, true, false, S::None, A::ShaderStorageWrite, L::General, IU::Storage,
     BU::Storage},
    {"StorageReadWrite", true, true, false, false, true, false, S::None,
     A::ShaderStorageRead | A::ShaderStorageWrite, L::General, IU::Storage, BU::Storage},
    // DrawIndirect also covers vkCmdDispatchIndirect's argument reads.
    {"IndirectArgs", false, false, false, true, true, false, S::DrawIndirect, A::IndirectCommandRead, L::Undefined,
     IU::None, BU::Indirect},
    {"Vertex", false, false, false, true, false, false, S::VertexInput, A::VertexAttributeRead, L::Undefined, IU::None,
     BU::Vertex},
    {"Index", false, false, false, true, false, false, S::VertexInput, A::IndexRead, L::Undefined, IU::None,
     BU::Index},
    {"Uniform", false, true, false, true, true, false, S::None, A::UniformRead, L::Undefined, IU::None,
     BU::Uniform},
    {"TransferSrc", false, false, false, false, true, true, S::Transfer, A::TransferRead, L::TransferSrc,
     IU::TransferSrc, BU::TransferSrc},
    {"TransferDst", true, false, false, false, true, true, S::Transfer, A::TransferWrite, L::TransferDst,
     IU::TransferDst, BU::TransferDst},
    // Presentation is outside the pipeline: only the layout matters.
    {"Present", false, false, true, false, false, false, S::None, A::None, L::PresentSrc, IU::None, BU::None},
}};

constexpr const AccessTraits& traits(Access access) { return kAccessTraits[static_cast<std::size_t>(access)]; }

constexpr PipelineStage shaderPipelineStages(ShaderStage shaderStages) {
  PipelineStage stages = PipelineStage::None;
  if (any(shaderStages & ShaderStage::Vertex)) stages |= PipelineStage::VertexShader;
  if (any(shaderStages & ShaderStage::Fragment)) stages |= PipelineStage::FragmentShader;
  if (any(shaderStages & ShaderStage::Compute)) stages |= PipelineStage::ComputeShader;
  return stages;
}

}  // namespace detail

constexpr bool isWrite(Access access) { return detail::traits(access).write; }
// Sampled, Storage*, Uniform: accesses made by shaders, which take a ShaderStage.
constexpr bool isShaderAccess(Access access) { return detail::traits(access).shader; }
constexpr bool isImageOnly(Access access) { return detail::traits(access).imageOnly; }
constexpr bool isBufferOnly(Access access) { return detail::traits(access).bufferOnly; }

constexpr bool allowedInPass(Access access, PassKind kind) {
  switch (kind) {
    case PassKind::Raster: return true;
    case PassKind::Compute: return detail::traits(access).inCompute;
    case PassKind::Transfer: return detail::traits(access).inTransfer;
  }
  return false;
}

constexpr ShaderStage defaultShaderStage(PassKind kind) {
  return kind == PassKind::Raster ? ShaderStage::Fragment
         : kind == PassKind::Compute ? ShaderStage::Compute
                                     : ShaderStage::None;
}

// Stages, access flags and image layout of `access` made from `shaderStages`
// (already resolved from the default; ignored for non-shader accesses).
constexpr AccessSync describeAccess(Access access, ShaderStage shaderStages) {
  const detail::AccessTraits& t = detail::traits(access);
  return {t.shader ? detail::shaderPipelineStages(shaderStages) : t.stages, t.access, t.layout};
}

constexpr ImageUsage imageUsageOf(Access access) { return detail::traits(access).imageUsage; }
constexpr BufferUsage bufferUsageOf(Access access) { return detail::traits(access).bufferUsage; }

// The one layout that serves two accesses of an image in the same pass, if any
// (e.g. DepthRead + Sampled -> DepthReadOnly; Sampled + ColorAttachment -> none).
std::optional<Layout> mergeLayouts(Layout a, Layout b);

constexpr std::string_view toString(Access access) { return detail::traits(access).name; }
std::string toString(ShaderStage stages);

}  // namespace sg::graph
