#include <stdexcept>

#include <shadelgraph/shadel/quadtree_allocator.hpp>

namespace sg::shadel {
namespace {

uint64_t spreadBits(uint32_t v) {
  uint64_t x = v;
  x = (x | (x << 16)) & 0x0000FFFF0000FFFFull;
  x = (x | (x << 8)) & 0x00FF00FF00FF00FFull;
  x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0Full;
  x = (x | (x << 2)) & 0x3333333333333333ull;
  x = (x | (x << 1)) & 0x5555555555555555ull;
  return x;
}

uint32_t compactBits(uint64_t x) {
  x &= 0x5555555555555555ull;
  x = (x | (x >> 1)) & 0x3333333333333333ull;
  x = (x | (x >> 2)) & 0x0F0F0F0F0F0F0F0Full;
  x = (x | (x >> 4)) & 0x00FF00FF00FF00FFull;
  x = (x | (x >> 8)) & 0x0000FFFF0000FFFFull;
  x = (x | (x >> 16)) & 0x00000000FFFFFFFFull;
  return static_cast<uint32_t>(x);
}

uint64_t mortonOf(glm::uvec2 p) { return spreadBits(p.x) | (spreadBits(p.y) << 1); }
glm::uvec2 originOf(uint64_t morton) { return {compactBits(morton), compactBits(morton >> 1)}; }

// Cells in a block of side 2^sizeLog2: also the Morton distance between buddies.
uint64_t cellsIn(uint32_t sizeLog2) { return uint64_t{1} << (2 * sizeLog2); }

}  // namespace

QuadtreeAllocator::QuadtreeAllocator(uint32_t gridLog2)
    : gridLog2_(gridLog2), freeCells_(cellsIn(gridLog2)), free_(gridLog2 + 1), live_(gridLog2 + 1) {
  if (gridLog2 > 16) throw std::invalid_argument("QuadtreeAllocator: grid larger than 2^16 cells a side");
  free_[gridLog2].insert(0);
}

std::optional<QuadtreeAllocator::Block> QuadtreeAllocator::allocate(uint32_t sizeLog2) {
  if (sizeLog2 > gridLog2_) return std::nullopt;
  uint32_t order = sizeLog2;
  while (order <= gridLog2_ && free_[order].empty()) ++order;
  if (order > gridLog2_) return std::nullopt;
  uint64_t morton = *free_[order].begin();
  free_[order].erase(free_[order].begin());
  // Split down to the requested size, keeping the first child each time.
  while (order > sizeLog2) {
    --order;
    for (uint64_t child = 1; child < 4; ++child) free_[order].insert(morton + child * cellsIn(order));
  }
  freeCells_ -= cellsIn(sizeLog2);
  live_[sizeLog2].insert(morton);
  return Block{originOf(morton), sizeLog2};
}

bool QuadtreeAllocator::release(const Block& block) {
  uint32_t order = block.sizeLog2;
  uint64_t morton = mortonOf(block.origin);
  if (order > gridLog2_ || live_[order].erase(morton) == 0) return false;
  freeCells_ += cellsIn(order);
  while (order < gridLog2_) {
    const uint64_t parent = morton & ~(cellsIn(order + 1) - 1);
    bool siblingsFree = true;
    for (uint64_t i = 0; i < 4 && siblingsFree; ++i) {
      const uint64_t sibling = parent + i * cellsIn(order);
      if (sibling != morton && !free_[order].count(sibling)) siblingsFree = false;
    }
    if (!siblingsFree) break;
    for (uint64_t i = 0; i < 4; ++i) free_[order].erase(parent + i * cellsIn(order));
    morton = parent;
    ++order;
  }
  free_[order].insert(morton);
  return true;
}

std::optional<uint32_t> QuadtreeAllocator::largestFreeBlockLog2() const {
  for (uint32_t order = gridLog2_ + 1; order-- > 0;)
    if (!free_[order].empty()) return order;
  return std::nullopt;
}

}  // namespace sg::shadel
