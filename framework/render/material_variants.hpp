#pragma once
// The two shaders the framework generates from a material layer's one GLSL
// source: the decoupled compute variant of one layer (a shadel per
// invocation, passes/layer-shade/shadel_context.glsl) and the forward fragment
// variant of a whole material stack (a pixel per invocation,
// passes/forward/forward_surface.glsl). An author writes neither: the
// generated text declares the layer images and accessors, includes the
// author's file (so errors point into it), and calls the layer function.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <shadelgraph/gpu/shader_compiler.hpp>
#include <shadelgraph/plugin/registry.hpp>
#include <shadelgraph/render/decoupled_frame.hpp>
#include <shadelgraph/render/layer_textures.hpp>

namespace sg::render {

// Set-0 bindings of a layer's decoupled variant, after the decoupled ones.
inline constexpr uint32_t kBindLayerOutput = kBindLayerImage;  // storage image it writes
inline constexpr uint32_t kBindLayerInputs = 14;               // + i: the i-th layer it reads (sampled)
inline constexpr uint32_t kMaxLayerReads = 8;
inline constexpr uint32_t kBindLayerHistory = 22;              // persistent: last frame's image of this layer
inline constexpr uint32_t kBindPreviousRemap = 23;             // persistent: last frame's remap table
// + i: the i-th frame resource the layer (decoupled) or the material's layers
// (forward, in stack order) sample; set 0 in both variants.
inline constexpr uint32_t kBindLayerFrameInputs = 24;
inline constexpr uint32_t kMaxLayerFrameInputs = 4;

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

gpu::ShaderRequest decoupledLayerVariant(const plugin::MaterialLayer& layer);
// Every layer of `stack` must run forward (Registry::materialFor picks the fallback).
gpu::ShaderRequest forwardMaterialVariant(const plugin::Registry& registry, const plugin::MaterialStack& stack);

// A layer or material whose generated variant failed to compile, as a
// PluginError naming it, its plugin and the file:line glslang reported (the
// author's own file when the error is there: the variant #includes it; its
// path on disk when the library read it from a plugin's directory).
plugin::PluginError layerCompileError(const gpu::ShaderCompileError& error, const gpu::ShaderLibrary& library,
                                      const std::string& what, const std::string& plugin);

}  // namespace sg::render
