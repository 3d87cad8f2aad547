#pragma once
// All triangle-ID maps live in one storage buffer, bound whole, so together
// they must fit the device's largest storage-buffer range. When the maps the
// objects ask for do not, the largest are made coarser (level 0 halved, one at
// a time) until they do: those objects shade at most at that density, rather
// than staying forward (MetalRoughSpheresNoTextures: 123 maps of 512²).
#include <cstdint>
#include <vector>

namespace sg::plugins {

// Texels of a map whose levels go from level0Size down to minLevelSize.
uint64_t idMapTexels(uint32_t level0Size, uint32_t minLevelSize);

// `wanted` level-0 sizes (powers of two), made to fit `budgetTexels` by
// halving the largest first, never below `floor`. The sum may still exceed the
// budget when every size is at the floor.
std::vector<uint32_t> fitIdMapSizes(std::vector<uint32_t> wanted, uint64_t budgetTexels, uint32_t minLevelSize,
                                    uint32_t floor);

}  // namespace sg::plugins
