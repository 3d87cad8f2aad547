#pragma once
// The forward fragment variant of a material stack, generated from its
// layers' GLSL sources: a pixel per invocation (forward_surface.glsl), each
// layer's value computed in stack order, the last one written out.
#include <shadelgraph/gpu/shader_compiler.hpp>
#include <shadelgraph/plugin/registry.hpp>

namespace sg::passes {

// Every layer of `stack` must run forward (Registry::materialFor picks the fallback).
// `plain`: for draws with DrawItem::plainSurface (position and normal varyings only).
// `alphaTest`: for alpha-mask draws (the only ones that may discard).
gpu::ShaderRequest forwardMaterialVariant(const plugin::Registry& registry, const plugin::MaterialStack& stack,
                                          bool plain = false, bool alphaTest = true);

}  // namespace sg::passes
