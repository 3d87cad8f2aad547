// Google Benchmark of declaring and compiling synthetic frame graphs
// (synthetic_graph.hpp), step by step. Google Benchmark repeats one input back
// to back, and the CPU learns a 100-pass graph (its branches, its data in the
// nearest caches): compiling it again runs about 1.7 times as fast as
// compiling a graph it has not just seen (BM_DeclareAndCompileDistinct). A
// frame loop, with a frame of other work between two compiles, does not get
// that. The scaling figure therefore comes
// from `shadelgraph bench graph`, which alternates sizes and distinct graphs
// in one run.

#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "synthetic_graph.hpp"

namespace {

using namespace sg::graph;

// Distinct graphs of one size that BM_DeclareAndCompileDistinct cycles through.
constexpr uint32_t kDistinctGraphs = 8;

void BM_DeclareAndCompile(benchmark::State& state) {
  const SyntheticGraph recipe = makeSyntheticGraph(static_cast<uint32_t>(state.range(0)), 42);
  const CompileOptions options = syntheticCompileOptions();
  std::size_t kept = 0;
  for (auto _ : state) {
    RenderGraph g;
    declare(g, recipe);
    CompiledPlan plan = compile(g, options);
    kept = plan.order.size();
    benchmark::DoNotOptimize(plan);
  }
  state.counters["kept_passes"] = static_cast<double>(kept);
  state.counters["per_pass"] = benchmark::Counter(static_cast<double>(state.iterations() * recipe.passes.size()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The same, cycling through distinct graphs of the same size.
void BM_DeclareAndCompileDistinct(benchmark::State& state) {
  std::vector<SyntheticGraph> recipes;
  for (uint32_t i = 0; i < kDistinctGraphs; ++i)
    recipes.push_back(makeSyntheticGraph(static_cast<uint32_t>(state.range(0)), 42 + i));
  const CompileOptions options = syntheticCompileOptions();
  std::size_t next = 0;
  for (auto _ : state) {
    RenderGraph g;
    declare(g, recipes[next]);
    CompiledPlan plan = compile(g, options);
    benchmark::DoNotOptimize(plan);
    next = (next + 1) % recipes.size();
  }
  state.counters["per_pass"] = benchmark::Counter(static_cast<double>(state.iterations() * recipes[0].passes.size()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Steady state of a frame loop: the same RenderGraph cleared and re-declared,
// compiled by a PlanCompiler that keeps its memory between frames.
void BM_DeclareAndCompileReusing(benchmark::State& state) {
  const SyntheticGraph recipe = makeSyntheticGraph(static_cast<uint32_t>(state.range(0)), 42);
  const CompileOptions options = syntheticCompileOptions();
  RenderGraph g;
  PlanCompiler compiler;
  for (auto _ : state) {
    g.clear();
    declare(g, recipe);
    const CompiledPlan& plan = compiler.compile(g, options);
    benchmark::DoNotOptimize(&plan);
  }
  state.counters["per_pass"] = benchmark::Counter(static_cast<double>(state.iterations() * recipe.passes.size()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_Declare(benchmark::State& state) {
  const SyntheticGraph recipe = makeSyntheticGraph(static_cast<uint32_t>(state.range(0)), 42);
  for (auto _ : state) {
    RenderGraph g;
    declare(g, recipe);
    benchmark::DoNotOptimize(g);
  }
}

void BM_Compile(benchmark::State& state) {
  const SyntheticGraph recipe = makeSyntheticGraph(static_cast<uint32_t>(state.range(0)), 42);
  const CompileOptions options = syntheticCompileOptions();
  RenderGraph g;
  declare(g, recipe);
  for (auto _ : state) {
    CompiledPlan plan = compile(g, options);
    benchmark::DoNotOptimize(plan);
  }
}

BENCHMARK(BM_DeclareAndCompile)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DeclareAndCompileDistinct)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DeclareAndCompileReusing)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Declare)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Compile)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
