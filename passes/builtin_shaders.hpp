#pragma once
// The GLSL of the built-in passes, materials and framework includes, embedded
// at build time under their paths from the project root.
#include <span>

#include <shadelgraph/gpu/shader_library.hpp>

namespace sg::gpu {
std::span<const EmbeddedShaderFile> builtinShaders();
}
