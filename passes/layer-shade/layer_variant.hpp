#pragma once
// The decoupled compute variant of a material layer, generated from its one
// GLSL source: a shadel per invocation (shadel_context.glsl), the layer
// images as set-0 bindings of the shared decoupled interface, the layer's
// textures and frame inputs, then the author's function.
#include <shadelgraph/gpu/shader_compiler.hpp>
#include <shadelgraph/plugin/material_layer.hpp>

namespace sg::passes {

// Rows of its chunk column each invocation of a layer-shade workgroup shades,
// for workgroups of `invocations` lanes (clamped to 8..64, a power of two):
// the device's subgroup size, so that one subgroup shades the whole chunk.
uint32_t chunkRowsPerInvocation(uint32_t invocations);

gpu::ShaderRequest decoupledLayerVariant(const plugin::MaterialLayer& layer, uint32_t rowsPerInvocation);

}  // namespace sg::passes
