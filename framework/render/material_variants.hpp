#pragma once
// The two shaders the framework generates from a material layer's one GLSL
// source: the decoupled compute variant of one layer (a shadel per
// invocation, passes/layer-shade/shadel_context.glsl) and the forward fragment
// variant of a whole material stack (a pixel per invocation,
// passes/forward/forward_surface.glsl). An author writes neither: the
// generated text declares the layer images and accessors, includes the
// author's file (so errors point into it), and calls the layer function.
#include <cstdint>
#include <string>

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

// GLSL image format qualifier of a layer image ("rgba16f"); throws for
// formats a layer cannot write.
std::string glslImageFormat(graph::Format format);

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
