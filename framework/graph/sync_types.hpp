#pragma once

#include <shadelgraph/graph/bitmask.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace sg::graph {

// The synchronization2 vocabulary in graph terms. The gpu layer maps each value
// 1:1 to VK_PIPELINE_STAGE_2_*, VK_ACCESS_2_* and VK_IMAGE_LAYOUT_*.

// 16 bits: the graph's accesses stay small (see ResourceAccess).
enum class PipelineStage : uint16_t {
  None = 0,
  DrawIndirect = 1u << 0,  // also covers vkCmdDispatchIndirect argument reads
  VertexInput = 1u << 1,   // index and vertex attribute fetch
  VertexShader = 1u << 2,
  FragmentShader = 1u << 3,
  EarlyFragmentTests = 1u << 4,
  LateFragmentTests = 1u << 5,
  ColorAttachmentOutput = 1u << 6,
  ComputeShader = 1u << 7,
  Transfer = 1u << 8,  // copies, blits, clears (VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT)
  AllCommands = 1u << 9,
};
template <>
struct EnableBitmask<PipelineStage> : std::true_type {};

enum class AccessFlag : uint16_t {
  None = 0,
  IndirectCommandRead = 1u << 0,
  IndexRead = 1u << 1,
  VertexAttributeRead = 1u << 2,
  UniformRead = 1u << 3,
  ShaderSampledRead = 1u << 4,
  ShaderStorageRead = 1u << 5,
  ShaderStorageWrite = 1u << 6,
  ColorAttachmentRead = 1u << 7,
  ColorAttachmentWrite = 1u << 8,
  DepthStencilRead = 1u << 9,
  DepthStencilWrite = 1u << 10,
  TransferRead = 1u << 11,
  TransferWrite = 1u << 12,
};
template <>
struct EnableBitmask<AccessFlag> : std::true_type {};

inline constexpr AccessFlag kWriteAccessFlags = AccessFlag::ShaderStorageWrite | AccessFlag::ColorAttachmentWrite |
                                                AccessFlag::DepthStencilWrite | AccessFlag::TransferWrite;

// Only write bits make a memory dependency's source scope meaningful.
constexpr AccessFlag writeBits(AccessFlag access) { return access & kWriteAccessFlags; }

enum class Layout : uint8_t {
  Undefined,
  General,
  ColorAttachment,
  DepthAttachment,
  DepthReadOnly,
  ShaderReadOnly,
  TransferSrc,
  TransferDst,
  PresentSrc,
};

// Where an external resource (imported, persistent, history) is at frame start
// or must be left at frame end: its layout and the last/next use outside the graph.
struct ResourceState {
  Layout layout = Layout::Undefined;
  PipelineStage stages = PipelineStage::None;
  AccessFlag access = AccessFlag::None;
  friend bool operator==(const ResourceState&, const ResourceState&) = default;
};
using ImportedState = ResourceState;
using FinalState = ResourceState;

std::string toString(PipelineStage stages);
std::string toString(AccessFlag access);
std::string_view toString(Layout layout);

}  // namespace sg::graph
