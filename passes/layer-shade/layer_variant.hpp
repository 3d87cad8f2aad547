#pragma once
// The decoupled compute variant of a material layer, generated from its one
// GLSL source: a shadel per invocation (shadel_context.glsl), the layer
// images as set-0 bindings of the shared decoupled interface, the layer's
// textures and frame inputs, then the author's function.
#include <shadelgraph/gpu/shader_compiler.hpp>
#include <shadelgraph/plugin/material_layer.hpp>

namespace sg::passes {

gpu::ShaderRequest decoupledLayerVariant(const plugin::MaterialLayer& layer);

}  // namespace sg::passes
