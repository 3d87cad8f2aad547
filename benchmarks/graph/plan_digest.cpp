// Every plan dump (toText and toJson) of 240 synthetic graphs (10, 100 and
// 1000 passes, 40 seeds each, aliasing on and off), compiled with one reused
// PlanCompiler as a frame loop does. A change meant to make compiling cheaper
// must leave this output byte-identical:
//   build/benchmarks/graph/plan_digest | md5sum
#include <cstdint>
#include <cstdio>
#include <string>

#include <shadelgraph/graph/plan_dump.hpp>

#include "synthetic_graph.hpp"

int main() {
  using namespace sg::graph;
  RenderGraph graph;
  PlanCompiler compiler;
  for (const uint32_t passes : {10u, 100u, 1000u}) {
    for (uint32_t seed = 0; seed < 40; ++seed) {
      const SyntheticGraph recipe = makeSyntheticGraph(passes, 1000 + seed);
      for (const bool aliasing : {true, false}) {
        CompileOptions options = syntheticCompileOptions();
        options.enableAliasing = aliasing;
        graph.clear();
        declare(graph, recipe);
        const CompiledPlan& plan = compiler.compile(graph, options);
        const std::string text = toText(plan) + toJson(plan);
        std::fwrite(text.data(), 1, text.size(), stdout);
      }
    }
  }
  return 0;
}
