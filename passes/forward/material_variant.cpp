#include "material_variant.hpp"

#include <sstream>

#include <shadelgraph/render/material_variants.hpp>

namespace sg::passes {

gpu::ShaderRequest forwardMaterialVariant(const plugin::Registry& registry, const plugin::MaterialStack& stack,
                                          bool plain, bool alphaTest) {
  std::ostringstream out;
  out << "#version 460\n"
      << "// Generated: forward variant of material '" << stack.name << "' (plugin '" << stack.plugin << "').\n"
      << "#define SG_FORWARD 1\n"
      << (plain ? "#define SG_FORWARD_PLAIN 1\n" : "")
      << (alphaTest ? "#define SG_FORWARD_ALPHA_TEST 1\n" : "")
      << "#include <passes/forward/forward_surface.glsl>\n";
  // Each layer's value, computed in stack order; reads of it return it.
  for (const auto& name : stack.layers) {
    const std::string id = plugin::glslName(name);
    out << "vec4 sgLayerValue_" << id << ";\n"
        << "vec4 sgLayer_" << id << "(ivec2 offset) { return sgLayerValue_" << id << "; }\n";
  }
  out << render::kLayerAccessorMacros;
  render::checkFrameInputCount(render::forwardFrameInputs(registry, stack).size(), "material '" + stack.name + "'", stack.plugin);
  uint32_t textureBinding = 0, frameInputBinding = 0;
  for (const auto& name : stack.layers) {
    const auto& layer = registry.layer(name);
    textureBinding = render::declareLayerTextures(out, layer, textureBinding);
    frameInputBinding = render::declareLayerFrameInputs(out, layer, frameInputBinding);
    render::includeLayerSource(out, layer);
  }
  out << "void main() {\n"
      << "  Surface s = sgForwardSurface();\n";
  for (const auto& name : stack.layers)
    out << "  sgLayerValue_" << plugin::glslName(name) << " = " << registry.layer(name).function << "(s);\n";
  out << "  sgWriteForward(sgLayerValue_" << plugin::glslName(stack.layers.back()) << ");\n"
      << "}\n";
  return {.path = "generated/materials/" + stack.name + (plain ? "-plain" : "") + (alphaTest ? "-alpha-test" : "") +
                   ".frag",
          .source = out.str(),
          .stage = gpu::ShaderStage::Fragment};
}

}  // namespace sg::passes
