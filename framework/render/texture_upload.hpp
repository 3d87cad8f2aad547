#pragma once
// A sampled RGBA8 texture on the GPU with its full mip chain (linear blits),
// left in SHADER_READ_ONLY for fragment and compute shaders.
#include <cstdint>
#include <string>

#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/gpu/memory.hpp>

namespace sg::gpu {
class Context;
}

namespace sg::render {

uint32_t mipCount(uint32_t w, uint32_t h);
gpu::Image uploadTexture(gpu::Context& context, gpu::MemoryAllocator& memory, uint32_t w, uint32_t h,
                         const uint8_t* pixels, bool srgb, const std::string& name, const std::string& category);

}  // namespace sg::render
