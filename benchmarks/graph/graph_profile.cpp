// A fixed declare + compile workload for callgrind, so that instruction counts
// are repeatable from run to run:
//   valgrind --tool=callgrind --toggle-collect='sg::graph::profiledRounds*'
//            build/benchmarks/graph/graph_profile [passes] [rounds] [fresh|unchanged]
// One PlanCompiler and RenderGraph are reused (as a frame loop does), 8
// distinct graphs compiled in turn; one untimed warm-up round first, so that
// only the steady state is collected. Instructions per compile: the collected
// total / (rounds x 8). Another argument "fresh" compiles with a new graph and
// compiler every time (allocations included); "unchanged" gives every graph its
// own RenderGraph and PlanCompiler, so each is declared again and its plan reused.
// A fourth argument "cold" writes 8 MiB between compiles (not collected), so
// each starts with its data out of L1 and L2, as in `shadelgraph bench graph`,
// where other sizes and modes run between: with --cache-sim=yes --D1=49152,12,64
// --LL=2097152,16,64 (this machine's L1d and L2) the misses are what a frame sees.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "synthetic_graph.hpp"

namespace sg::graph {

constexpr uint32_t kGraphs = 8;

enum class Mode { Reused, Fresh, Unchanged };

// The graphs and compilers a mode compiles with: one shared (reused), or one per recipe (unchanged).
struct Workload {
  Mode mode = Mode::Reused;
  std::vector<uint64_t> evict;  // empty: no eviction
  std::vector<RenderGraph> graphs = std::vector<RenderGraph>(kGraphs);
  std::vector<PlanCompiler> compilers = std::vector<PlanCompiler>(kGraphs);
};

// Evicts the compile's data from the caches (callgrind stops collecting inside: see --toggle-collect).
[[gnu::noinline]] void profiledRoundsEvict(std::vector<uint64_t>& junk) {
  for (std::size_t i = 0; i < junk.size(); i += 8) junk[i] += i;
}

[[gnu::always_inline]] inline std::size_t runRounds(const std::vector<SyntheticGraph>& recipes, uint32_t rounds,
                                                    Workload& work, const CompileOptions& options) {
  std::size_t kept = 0;
  for (uint32_t round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < recipes.size(); ++i) {
      if (!work.evict.empty()) profiledRoundsEvict(work.evict);
      if (work.mode == Mode::Fresh) {
        RenderGraph g;
        declare(g, recipes[i]);
        kept += compile(g, options).order.size();
      } else {
        const std::size_t own = work.mode == Mode::Unchanged ? i : 0;
        work.graphs[own].clear();
        declare(work.graphs[own], recipes[i]);
        kept += work.compilers[own].compile(work.graphs[own], options).order.size();
      }
    }
  }
  return kept;
}

// Two out-of-line copies: callgrind collects only inside the second (--toggle-collect).
[[gnu::noinline]] std::size_t warmUpRounds(const std::vector<SyntheticGraph>& recipes, Workload& work,
                                           const CompileOptions& options) {
  return runRounds(recipes, 1, work, options);
}
[[gnu::noinline]] std::size_t profiledRounds(const std::vector<SyntheticGraph>& recipes, uint32_t rounds,
                                             Workload& work, const CompileOptions& options) {
  return runRounds(recipes, rounds, work, options);
}

}  // namespace sg::graph

int main(int argc, char** argv) {
  using namespace sg::graph;
  uint32_t passes = argc > 1 ? static_cast<uint32_t>(std::strtoul(argv[1], nullptr, 10)) : 100;
  const uint32_t rounds = argc > 2 ? static_cast<uint32_t>(std::strtoul(argv[2], nullptr, 10)) : 10;
  Workload work;
  const char* modeName = argc > 3 ? argv[3] : "reused";
  if (std::strcmp(modeName, "fresh") == 0) work.mode = Mode::Fresh;
  else if (std::strcmp(modeName, "unchanged") == 0) work.mode = Mode::Unchanged;
  else if (std::strcmp(modeName, "reused") != 0) passes = 0;
  const bool cold = argc > 4 && std::strcmp(argv[4], "cold") == 0;
  if (cold) work.evict.assign(std::size_t{8} << 17, 0);  // 8 MiB
  if (argc > 4 && !cold) passes = 0;
  if (passes < 2 || rounds == 0) {
    std::fprintf(stderr, "usage: graph_profile [passes >= 2] [rounds >= 1] [reused|fresh|unchanged] [cold]\n");
    return 1;
  }
  std::vector<SyntheticGraph> recipes;
  for (uint32_t g = 0; g < kGraphs; ++g) recipes.push_back(makeSyntheticGraph(passes, 42 + g));
  const CompileOptions options = syntheticCompileOptions();
  warmUpRounds(recipes, work, options);
  const std::size_t kept = profiledRounds(recipes, rounds, work, options);
  std::printf("%u passes, %u rounds x %u graphs (%s%s), %zu kept passes\n", passes, rounds, kGraphs, modeName,
              cold ? ", cold" : "", kept);
  return 0;
}
