#include <shadelgraph/render/material_variants.hpp>

#include <sstream>

namespace sg::render {
namespace {

void defineParameters(std::ostringstream& out, const plugin::MaterialLayer& layer) {
  for (const auto& [name, value] : layer.parameters) out << "#define " << name << " " << value << "\n";
}

// The layer's own textures, set 2 from binding `first` on.
uint32_t declareTextures(std::ostringstream& out, const plugin::MaterialLayer& layer, uint32_t first) {
  for (const auto& texture : layer.textures)
    out << "layout(set = " << kLayerTextureSet << ", binding = " << first++ << ") uniform sampler2D " << texture.name
        << ";\n";
  return first;
}

// The frame resources a variant samples, set 0 from binding kBindLayerFrameInputs + `first` on.
uint32_t declareFrameInputs(std::ostringstream& out, const plugin::MaterialLayer& layer, uint32_t first) {
  for (const auto& input : layer.frameInputs)
    out << "layout(set = 0, binding = " << kBindLayerFrameInputs + first++ << ") uniform sampler2D " << input.name
        << ";\n";
  return first;
}

void checkFrameInputCount(size_t count, const std::string& what, const std::string& plugin) {
  if (count > kMaxLayerFrameInputs)
    throw plugin::PluginError(what + " (plugin '" + plugin + "') samples more than " +
                              std::to_string(kMaxLayerFrameInputs) + " frame resources");
}

void undefineParameters(std::ostringstream& out, const plugin::MaterialLayer& layer) {
  for (const auto& [name, value] : layer.parameters) out << "#undef " << name << "\n";
}

// sgLayer(name) and sgLayerAt(name, offset) call the generated sgLayer_<name>;
// the extra step expands a parameter macro given as the name.
const char* kAccessorMacros =
    "#define SG_LAYER_CALL(name, offset) sgLayer_##name(offset)\n"
    "#define sgLayer(name) SG_LAYER_CALL(name, ivec2(0))\n"
    "#define sgLayerAt(name, offset) SG_LAYER_CALL(name, offset)\n";

bool isHalfFloat(graph::Format format) {
  return format == graph::Format::R16F || format == graph::Format::RG16F || format == graph::Format::RGBA16F;
}

}  // namespace

plugin::PluginError layerCompileError(const gpu::ShaderCompileError& error, const gpu::ShaderLibrary& library,
                                      const std::string& what, const std::string& plugin) {
  const auto file = library.fileOf(error.file());
  return plugin::PluginError(what + " (plugin '" + plugin + "') does not compile: " +
                             (file ? file->string() : error.file()) + ":" + std::to_string(error.line()) + ": " +
                             error.diagnostics().front().message);
}

std::string glslImageFormat(graph::Format format) {
  switch (format) {
    case graph::Format::R16F: return "r16f";
    case graph::Format::RG16F: return "rg16f";
    case graph::Format::RGBA16F: return "rgba16f";
    case graph::Format::R32F: return "r32f";
    case graph::Format::RG32F: return "rg32f";
    case graph::Format::RGBA32F: return "rgba32f";
    case graph::Format::RGBA8Unorm: return "rgba8";
    case graph::Format::R8Unorm: return "r8";
    default: throw plugin::PluginError("a material layer cannot write this image format");
  }
}

std::vector<const plugin::LayerFrameInput*> forwardFrameInputs(const plugin::Registry& registry,
                                                               const plugin::MaterialStack& stack) {
  std::vector<const plugin::LayerFrameInput*> inputs;
  for (const auto& name : stack.layers)
    for (const auto& input : registry.layer(name).frameInputs) inputs.push_back(&input);
  return inputs;
}

graph::ResourceHandle frameInputImage(const std::map<std::string, graph::ResourceHandle>& images,
                                      const plugin::MaterialLayer& layer, const plugin::LayerFrameInput& input) {
  auto it = images.find(input.resource);
  if (it == images.end())
    throw plugin::PluginError("material layer '" + layer.name + "' (plugin '" + layer.plugin +
                              "') samples frame resource '" + input.resource +
                              "', which no earlier pass of the frame wrote (add a pass that writes it before the "
                              "shading passes)");
  return it->second;
}

gpu::ShaderRequest decoupledLayerVariant(const plugin::MaterialLayer& layer) {
  checkFrameInputCount(layer.frameInputs.size(), "material layer '" + layer.name + "'", layer.plugin);
  if (layer.reads.size() > kMaxLayerReads)
    throw plugin::PluginError("material layer '" + layer.name + "' (plugin '" + layer.plugin + "') reads more than " +
                              std::to_string(kMaxLayerReads) + " layers");
  std::ostringstream out;
  out << "#version 460\n"
      << "// Generated: decoupled variant of material layer '" << layer.name << "' (plugin '" << layer.plugin
      << "').\n"
      << "#define SG_DECOUPLED 1\n"
      << "#include <passes/layer-shade/shadel_context.glsl>\n"
      << "layout(set = 0, binding = " << kBindLayerOutput << ", " << glslImageFormat(layer.format)
      << ") uniform writeonly image2D sgLayerOutput;\n";
  for (size_t i = 0; i < layer.reads.size(); ++i) {
    const std::string name = plugin::glslName(layer.reads[i].layer);
    out << "layout(set = 0, binding = " << kBindLayerInputs + i << ") uniform sampler2D sgLayerImage_" << name
        << ";\n"
        << "vec4 sgLayer_" << name << "(ivec2 offset) { return sgFetchLayer(sgLayerImage_" << name
        << ", offset); }\n";
  }
  if (layer.persistent) {
    out << "layout(set = 0, binding = " << kBindLayerHistory << ") uniform sampler2D sgLayerHistory;\n"
        << "layout(set = 0, binding = " << kBindPreviousRemap
        << ", std430) readonly buffer PreviousRemap { SgRemapEntry previousRemap[]; };\n"
        << "bool sgReusedPrevious = false;\n"
        << "// The paper's GetIndexPrevSampleVirtualCoords: this shadel's value last frame, if it was shaded.\n"
        << "bool sgPrevious(out vec4 value) {\n"
        << "  value = vec4(0.0);\n"
        << "  if (sgPush.historyValid == 0u) return false;\n"
        << "  SgShadelAddress a = sgShadelAddress(sgShadel.shadel, params.entriesPerSideLog2);\n"
        << "  uint physical = sgPhysicalChunk(previousRemap[a.entryIndex], a.chunkIndex);\n"
        << "  if (physical == SG_INVALID_CHUNK) return false;\n"
        << "  value = texelFetch(sgLayerHistory, ivec2(sgStorageTexel(physical, a.texelIndex, "
           "params.storageWidthChunks)), 0);\n"
        << "  sgReusedPrevious = true;\n"
        << "  return true;\n"
        << "}\n";
  } else {
    out << "bool sgPrevious(out vec4 value) { value = vec4(0.0); return false; }\n";
  }
  out << kAccessorMacros;
  declareTextures(out, layer, 0);
  declareFrameInputs(out, layer, 0);
  defineParameters(out, layer);
  out << "#include <" << layer.source << ">\n";
  undefineParameters(out, layer);
  out << "shared uint sgReusedCount, sgComputedCount;\n"
      << "void main() {\n"
      << "  if (!sgWorkGroupInList()) return;  // the surplus of a dispatch's last row\n"
      << "  Surface s;\n"
      << "  bool onSurface = sgBeginShadel(s);\n"
      << "  vec4 value = onSurface ? " << layer.function << "(s) : vec4(0.0);\n"
      // Half floats overflow to Inf above 65,504 on some devices (lavapipe saturates): clamp, so
      // composite's filter never weighs an Inf (Inf x 0 = NaN).
      << "  imageStore(sgLayerOutput, sgShadel.target, "
      << (isHalfFloat(layer.format) ? "clamp(value, -65504.0, 65504.0)" : "value") << ");\n";
  if (layer.persistent) {
    // One atomic per workgroup, not per shadel.
    out << "  if (gl_LocalInvocationIndex == 0u) { sgReusedCount = 0u; sgComputedCount = 0u; }\n"
        << "  barrier();\n"
        << "  if (onSurface && sgReusedPrevious) atomicAdd(sgReusedCount, 1u);\n"
        << "  if (onSurface && !sgReusedPrevious) atomicAdd(sgComputedCount, 1u);\n"
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

gpu::ShaderRequest forwardMaterialVariant(const plugin::Registry& registry, const plugin::MaterialStack& stack) {
  std::ostringstream out;
  out << "#version 460\n"
      << "// Generated: forward variant of material '" << stack.name << "' (plugin '" << stack.plugin << "').\n"
      << "#define SG_FORWARD 1\n"
      << "#include <passes/forward/forward_surface.glsl>\n";
  // Each layer's value, computed in stack order; reads of it return it.
  for (const auto& name : stack.layers) {
    const std::string id = plugin::glslName(name);
    out << "vec4 sgLayerValue_" << id << ";\n"
        << "vec4 sgLayer_" << id << "(ivec2 offset) { return sgLayerValue_" << id << "; }\n";
  }
  out << kAccessorMacros;
  checkFrameInputCount(forwardFrameInputs(registry, stack).size(), "material '" + stack.name + "'", stack.plugin);
  uint32_t textureBinding = 0, frameInputBinding = 0;
  for (const auto& name : stack.layers) {
    const auto& layer = registry.layer(name);
    textureBinding = declareTextures(out, layer, textureBinding);
    frameInputBinding = declareFrameInputs(out, layer, frameInputBinding);
    defineParameters(out, layer);
    out << "#include <" << layer.source << ">\n";
    undefineParameters(out, layer);
  }
  out << "void main() {\n"
      << "  Surface s = sgForwardSurface();\n";
  for (const auto& name : stack.layers)
    out << "  sgLayerValue_" << plugin::glslName(name) << " = " << registry.layer(name).function << "(s);\n";
  out << "  sgWriteForward(sgLayerValue_" << plugin::glslName(stack.layers.back()) << ");\n"
      << "}\n";
  return {.path = "generated/materials/" + stack.name + ".frag", .source = out.str(),
          .stage = gpu::ShaderStage::Fragment};
}

}  // namespace sg::render
