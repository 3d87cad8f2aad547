#pragma once
// A device-local buffer filled once from host memory (through a staging
// buffer, waited for), readable by every stage afterwards.
#include <cstddef>

#include <shadelgraph/gpu/buffer.hpp>

namespace sg::render {

// `concurrent`: shared by the graphics and async compute queue families.
gpu::Buffer uploadBuffer(gpu::Context& context, gpu::MemoryAllocator& memory, const void* data, size_t bytes,
                         VkBufferUsageFlags usage, const char* name, bool concurrent = false);

}  // namespace sg::render
