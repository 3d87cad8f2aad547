#include <shadelgraph/render/material_variants.hpp>

namespace sg::render {

uint32_t declareLayerTextures(std::ostream& out, const plugin::MaterialLayer& layer, uint32_t first) {
  for (const auto& texture : layer.textures)
    out << "layout(set = " << kLayerTextureSet << ", binding = " << first++ << ") uniform sampler2D " << texture.name
        << ";\n";
  return first;
}

uint32_t declareLayerFrameInputs(std::ostream& out, const plugin::MaterialLayer& layer, uint32_t first) {
  for (const auto& input : layer.frameInputs)
    out << "layout(set = 0, binding = " << kBindLayerFrameInputs + first++ << ") uniform sampler2D " << input.name
        << ";\n";
  return first;
}

void includeLayerSource(std::ostream& out, const plugin::MaterialLayer& layer) {
  for (const auto& [name, value] : layer.parameters) out << "#define " << name << " " << value << "\n";
  out << "#include <" << layer.source << ">\n";
  for (const auto& [name, value] : layer.parameters) out << "#undef " << name << "\n";
}

void checkFrameInputCount(size_t count, const std::string& what, const std::string& plugin) {
  if (count > kMaxLayerFrameInputs)
    throw plugin::PluginError(what + " (plugin '" + plugin + "') samples more than " +
                              std::to_string(kMaxLayerFrameInputs) + " frame resources");
}

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

}  // namespace sg::render
