#pragma once
// Where a compiled plan's transients need the most memory at once: the
// position in the execution order at which the transients in use (first use
// <= position <= last use) add up to the most bytes. No placement can alias
// those with one another, so their total is the least the heaps can hold with
// aliasing, whatever the packing; the rest of the heaps is packing loss.
#include <cstdint>
#include <string>
#include <vector>

#include <shadelgraph/graph/compiled_plan.hpp>

namespace sg::graph {

struct TransientPeak {
  uint32_t position = kInvalidIndex;  // in CompiledPlan::order; kInvalidIndex without transients
  std::string pass;                   // the pass at that position
  uint64_t bytes = 0;                 // the transients in use there, their placed sizes
  struct Live {
    std::string name;
    uint64_t bytes = 0;
  };
  std::vector<Live> live;  // largest first
};

TransientPeak transientPeak(const CompiledPlan& plan);

}  // namespace sg::graph
