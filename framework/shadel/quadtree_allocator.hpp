#pragma once
// A buddy allocator over a 2^n x 2^n grid of cells, handing out aligned
// power-of-two squares (a region quadtree).
//
// Why this and not shelf packing: every request of shadel space is a
// power-of-two square (one detail level, in remap entries), and a buddy
// quadtree packs those with no internal waste, in O(log n) per operation,
// and merges freed siblings back into their parent, so space freed by
// departing instances is reusable by larger ones without any compaction.
// Shelves would fragment under churn. Free blocks are kept per size in
// Morton order and the lowest is taken first, so allocation is deterministic
// and packs toward the origin.
#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include <glm/glm.hpp>

namespace sg::shadel {

class QuadtreeAllocator {
 public:
  struct Block {
    glm::uvec2 origin{0};   // in cells, a multiple of 2^sizeLog2
    uint32_t sizeLog2 = 0;  // the block is 2^sizeLog2 cells a side
    bool operator==(const Block&) const = default;
  };

  // A grid of 2^gridLog2 cells a side (gridLog2 <= 16), all free.
  explicit QuadtreeAllocator(uint32_t gridLog2);

  // The lowest free block of that size; nullopt when none is left (or the
  // size exceeds the grid).
  std::optional<Block> allocate(uint32_t sizeLog2);
  // Returns a block from allocate(); buddies that are all free merge. False
  // (and nothing changes) for anything that is not a live block.
  bool release(const Block& block);

  uint32_t gridLog2() const { return gridLog2_; }
  uint64_t freeCells() const { return freeCells_; }
  uint64_t totalCells() const { return uint64_t{1} << (2 * gridLog2_); }
  // log2 of the largest free block's side; nullopt when the grid is full.
  std::optional<uint32_t> largestFreeBlockLog2() const;

 private:
  uint32_t gridLog2_;
  uint64_t freeCells_;
  std::vector<std::set<uint64_t>> free_;  // [sizeLog2]: Morton codes of free blocks' origins
  std::vector<std::set<uint64_t>> live_;  // [sizeLog2]: the same for allocated blocks
};

}  // namespace sg::shadel
