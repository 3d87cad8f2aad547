// A fixed declare + compile workload for callgrind, so that instruction counts
// are repeatable from run to run:
//   valgrind --tool=callgrind --toggle-collect='sg::graph::profiledRounds*'
//            build/benchmarks/graph/graph_profile [passes] [rounds] [fresh]
// One PlanCompiler and RenderGraph are reused (as a frame loop does), 8
// distinct graphs compiled in turn; one untimed warm-up round first, so that
// only the steady state is collected. Instructions per compile: the collected
// total / (rounds x 8). Another argument "fresh" compiles with a new graph and
// compiler every time (allocations included).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "synthetic_graph.hpp"

namespace sg::graph {

constexpr uint32_t kGraphs = 8;

[[gnu::always_inline]] inline std::size_t runRounds(const std::vector<SyntheticGraph>& recipes, uint32_t rounds,
                                                    bool fresh, RenderGraph& graph, PlanCompiler& compiler,
                                                    const CompileOptions& options) {
  std::size_t kept = 0;
  for (uint32_t round = 0; round < rounds; ++round) {
    for (const SyntheticGraph& recipe : recipes) {
      if (fresh) {
        RenderGraph g;
        declare(g, recipe);
        kept += compile(g, options).order.size();
      } else {
        graph.clear();
        declare(graph, recipe);
        kept += compiler.compile(graph, options).order.size();
      }
    }
  }
  return kept;
}

// Two out-of-line copies: callgrind collects only inside the second (--toggle-collect).
[[gnu::noinline]] std::size_t warmUpRounds(const std::vector<SyntheticGraph>& recipes, bool fresh, RenderGraph& graph,
                                           PlanCompiler& compiler, const CompileOptions& options) {
  return runRounds(recipes, 1, fresh, graph, compiler, options);
}
[[gnu::noinline]] std::size_t profiledRounds(const std::vector<SyntheticGraph>& recipes, uint32_t rounds, bool fresh,
                                             RenderGraph& graph, PlanCompiler& compiler, const CompileOptions& options) {
  return runRounds(recipes, rounds, fresh, graph, compiler, options);
}

}  // namespace sg::graph

int main(int argc, char** argv) {
  using namespace sg::graph;
  const uint32_t passes = argc > 1 ? static_cast<uint32_t>(std::strtoul(argv[1], nullptr, 10)) : 100;
  const uint32_t rounds = argc > 2 ? static_cast<uint32_t>(std::strtoul(argv[2], nullptr, 10)) : 10;
  const bool fresh = argc > 3 && std::strcmp(argv[3], "fresh") == 0;
  if (passes < 2 || rounds == 0) {
    std::fprintf(stderr, "usage: graph_profile [passes >= 2] [rounds >= 1] [fresh]\n");
    return 1;
  }
  std::vector<SyntheticGraph> recipes;
  for (uint32_t g = 0; g < kGraphs; ++g) recipes.push_back(makeSyntheticGraph(passes, 42 + g));
  const CompileOptions options = syntheticCompileOptions();
  RenderGraph graph;
  PlanCompiler compiler;
  warmUpRounds(recipes, fresh, graph, compiler, options);
  const std::size_t kept = profiledRounds(recipes, rounds, fresh, graph, compiler, options);
  std::printf("%u passes, %u rounds x %u graphs (%s), %zu kept passes\n", passes, rounds, kGraphs,
              fresh ? "fresh" : "reused", kept);
  return 0;
}
