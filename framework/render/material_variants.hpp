#pragma once
// What every shading path's generated material variant is built from. A
// material layer is one GLSL source; each pass that runs materials (the
// forward fragment variant in passes/forward, the decoupled compute variant
// in passes/layer-shade) generates a shader that declares the layer's
// textures, frame inputs and accessors with these pieces, includes the
// author's file (so errors point into it), and calls the layer function.
#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include <shadelgraph/gpu/shader_compiler.hpp>
#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/plugin/registry.hpp>
#include <shadelgraph/render/layer_textures.hpp>

namespace sg::render {

// + i: the i-th frame resource the layer (decoupled) or the material's layers
// (forward, in stack order) sample; set 0 in every variant.
inline constexpr uint32_t kBindLayerFrameInputs = 24;
inline constexpr uint32_t kMaxLayerFrameInputs = 4;

// sgLayer(name) and sgLayerAt(name, offset) call the variant's sgLayer_<name>;
// the extra step expands a parameter macro given as the name.
inline constexpr const char* kLayerAccessorMacros =
    "#define SG_LAYER_CALL(name, offset) sgLayer_##name(offset)\n"
    "#define sgLayer(name) SG_LAYER_CALL(name, ivec2(0))\n"
    "#define sgLayerAt(name, offset) SG_LAYER_CALL(name, offset)\n";

// The layer's own textures, set kLayerTextureSet from binding `first` on;
// returns the next free binding.
uint32_t declareLayerTextures(std::ostream& out, const plugin::MaterialLayer& layer, uint32_t first);
// The frame resources the layer samples, set 0 from kBindLayerFrameInputs + `first`;
// returns the next free index.
uint32_t declareLayerFrameInputs(std::ostream& out, const plugin::MaterialLayer& layer, uint32_t first);
// The layer's parameters as #defines around an #include of its source.
void includeLayerSource(std::ostream& out, const plugin::MaterialLayer& layer);
// Throws naming `what` and its plugin when it samples more frame resources than bind.
void checkFrameInputCount(size_t count, const std::string& what, const std::string& plugin);

// GLSL image format qualifier of a layer image ("rgba16f"); throws for
// formats a layer cannot write.
std::string glslImageFormat(graph::Format format);

// The frame resources the forward variant of `stack` samples, in binding order.
std::vector<const plugin::LayerFrameInput*> forwardFrameInputs(const plugin::Registry& registry,
                                                               const plugin::MaterialStack& stack);
// The frame resource `input` of `layer` among `images` (a frame's resources);
// throws naming the layer, its plugin and the resource when no pass wrote it.
graph::ResourceHandle frameInputImage(const std::map<std::string, graph::ResourceHandle>& images,
                                      const plugin::MaterialLayer& layer, const plugin::LayerFrameInput& input);

// A layer or material whose generated variant failed to compile, as a
// PluginError naming it, its plugin and the file:line glslang reported (the
// author's own file when the error is there: the variant #includes it; its
// path on disk when the library read it from a plugin's directory).
plugin::PluginError layerCompileError(const gpu::ShaderCompileError& error, const gpu::ShaderLibrary& library,
                                      const std::string& what, const std::string& plugin);

}  // namespace sg::render
