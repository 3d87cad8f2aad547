#include "layer_variant.hpp"

#include <algorithm>
#include <bit>
#include <sstream>
#include <stdexcept>

#include <decoupled_frame.hpp>
#include <shadelgraph/render/material_variants.hpp>

namespace sg::passes {
namespace {

bool isHalfFloat(graph::Format format) {
  return format == graph::Format::R16F || format == graph::Format::RG16F || format == graph::Format::RGBA16F;
}

}  // namespace

uint32_t chunkRowsPerInvocation(uint32_t invocations) {
  return 64u / std::bit_floor(std::clamp(invocations, 8u, 64u));
}

gpu::ShaderRequest decoupledLayerVariant(const plugin::MaterialLayer& layer, uint32_t rowsPerInvocation) {
  if (rowsPerInvocation == 0 || rowsPerInvocation > 8 || !std::has_single_bit(rowsPerInvocation))
    throw std::invalid_argument("layer-shade: rows per invocation must be 1, 2, 4 or 8, not " +
                                std::to_string(rowsPerInvocation));
  render::checkFrameInputCount(layer.frameInputs.size(), "material layer '" + layer.name + "'", layer.plugin);
  if (layer.reads.size() > kMaxLayerReads)
    throw plugin::PluginError("material layer '" + layer.name + "' (plugin '" + layer.plugin + "') reads more than " +
                              std::to_string(kMaxLayerReads) + " layers");
  std::ostringstream out;
  out << "#version 460\n"
      << "// Generated: decoupled variant of material layer '" << layer.name << "' (plugin '" << layer.plugin
      << "').\n"
      << "#define SG_DECOUPLED 1\n"
      << "#define SG_CHUNK_ROWS_PER_INVOCATION " << rowsPerInvocation << "u\n"
      << "#include <passes/layer-shade/shadel_context.glsl>\n"
      << "layout(set = 0, binding = " << kBindLayerOutput << ", " << render::glslImageFormat(layer.format)
      << ") uniform writeonly image2D sgLayerOutput;\n";
  for (size_t i = 0; i < layer.reads.size(); ++i) {
    const std::string name = plugin::glslName(layer.reads[i].layer);
    out << "layout(set = 0, binding = " << kBindLayerInputs + i << ") uniform sampler2D sgLayerImage_" << name
        << ";\n"
        << "vec4 sgLayer_" << name << "(ivec2 offset) { return sgFetchLayer(sgLayerImage_" << name
        << ", offset); }\n";
  }
  if (layer.keepsValues()) {
    out << "layout(set = 0, binding = " << kBindLayerHistory << ") uniform sampler2D sgLayerHistory;\n"
        << "bool sgReusedPrevious = false;\n"
        << "// The paper's GetIndexPrevSampleVirtualCoords: this shadel's value last frame, if it was shaded.\n"
        << "// Stable allocation: a chunk stored last frame too is at the same place in last frame's image.\n"
        << "bool sgPrevious(out vec4 value) {\n"
        << "  value = vec4(0.0);\n"
        << "  if (sgPush.historyValid == 0u) return false;\n"
        << "  SgShadelAddress a = sgShadelAddress(sgShadel.shadel, params.entriesPerSideLog2);\n"
        << "  SgRemapEntry entry = remap[a.entryIndex];\n"
        << "  if (!sgChunkKept(entry, a.chunkIndex)) return false;\n"
        << "  uint physical = sgStoredChunk(entry, a.chunkIndex);\n"
        << "  value = texelFetch(sgLayerHistory, ivec2(sgStorageTexel(physical, a.texelIndex, "
           "params.storageWidthChunks)), 0);\n"
        << "  sgReusedPrevious = true;\n"
        << "  return true;\n"
        << "}\n";
  } else {
    out << "bool sgPrevious(out vec4 value) { value = vec4(0.0); return false; }\n";
  }
  out << render::kLayerAccessorMacros;
  render::declareLayerTextures(out, layer, 0);
  render::declareLayerFrameInputs(out, layer, 0);
  render::includeLayerSource(out, layer);
  out << "shared uint sgReusedCount, sgComputedCount;\n"
      << "void main() {\n"
      << "  if (!sgWorkGroupInList()) return;  // the surplus of a dispatch's last row\n"
      << "  SgChunkSetup sgChunk = sgChunkSetup();\n";
  if (layer.keepsValues()) out << "  uint sgReused = 0u, sgComputed = 0u;  // shadels kept from last frame, and computed\n";
  if (!layer.keepsValues()) {
    // Only the shadels composite reads (shadel masks; never with kept values,
    // whose stored shadels may be served later). The last layer counts those it leaves out.
    out << "  uvec2 sgMarked = sgChunk.shadelMask;\n"
        << "  uint sgMarkedCount = uint(bitCount(sgMarked.x) + bitCount(sgMarked.y));\n"
        << "  if (sgPush.countSkipped != 0u && gl_LocalInvocationIndex == 0u && sgMarkedCount < 64u)\n"
        << "    atomicAdd(counters.shadelsSkipped, 64u - sgMarkedCount);\n";
  }
  // Kept while its object's bit for this layer is set (layer_rate.hpp): one read per chunk.
  if (layer.viewIndependent())
    out << "  bool keep = (objects[sgPush.objectIndex].keepLayers >> sgPush.persistentSlot & 1u) != 0u;\n";
  if (layer.keepsValues()) {
    out << "  for (uint sgRow = sgFirstShadelRow(); sgRow < sgFirstShadelRow() + SG_CHUNK_ROWS_PER_INVOCATION; ++sgRow) {\n"
        << "    uint sgTexel = sgChunkTexel(sgRow);\n";
  } else {
    // Only the marked shadels, in full lanes (marked_shadels.glsl).
    out << "  uint64_t sgLeft = sgSkipMarked(packUint2x32(sgMarked), gl_LocalInvocationIndex);\n"
        << "  for (; sgLeft != 0ul; sgLeft = sgSkipMarked(sgLeft, SG_LAYER_SHADE_INVOCATIONS)) {\n"
        << "    uint sgTexel = sgFirstMarkedTexel(sgLeft);\n";
  }
  out << "    Surface s;\n"
      << "    bool onSurface = sgBeginShadel(sgChunk, sgTexel, s);\n"
      << "    vec4 value = vec4(0.0);\n";
  if (layer.viewIndependent()) {
    // Last frame's value where the shadel was stored and kept, else computed.
    if (layer.keepsValues()) out << "    sgReusedPrevious = false;  // set by sgPrevious\n";
    out << "    if (onSurface && !(keep && sgPrevious(value))) value = " << layer.function << "(s);\n";
  } else {
    out << "    if (onSurface) value = " << layer.function << "(s);\n";
  }
  out
      // Half floats overflow to Inf above 65,504 on some devices (lavapipe saturates): clamp, so
      // composite's filter never weighs an Inf (Inf x 0 = NaN).
      << "    imageStore(sgLayerOutput, sgShadel.target, "
      << (isHalfFloat(layer.format) ? "clamp(value, -65504.0, 65504.0)" : "value") << ");\n";
  if (layer.keepsValues()) {
    out << "    if (onSurface && sgReusedPrevious) ++sgReused;\n"
        << "    if (onSurface && !sgReusedPrevious) ++sgComputed;\n";
  }
  out << "  }\n";
  if (layer.keepsValues()) {
    // One atomic per workgroup, not per shadel.
    out << "  if (gl_LocalInvocationIndex == 0u) { sgReusedCount = 0u; sgComputedCount = 0u; }\n"
        << "  barrier();\n"
        << "  atomicAdd(sgReusedCount, sgReused);\n"
        << "  atomicAdd(sgComputedCount, sgComputed);\n"
        << "  barrier();\n"
        << "  if (gl_LocalInvocationIndex == 0u) {\n"
        << "    atomicAdd(counters.layerReused[sgPush.persistentSlot], sgReusedCount);\n"
        << "    atomicAdd(counters.layerComputed[sgPush.persistentSlot], sgComputedCount);\n"
        << "  }\n";
  }
  out << "}\n";
  return {.path = "generated/layers/" + layer.name + ".comp", .source = out.str(),
          .stage = gpu::ShaderStage::Compute};
}

}  // namespace sg::passes
