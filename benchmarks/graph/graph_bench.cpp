// Declare + compile cost of synthetic frame graphs shaped like real ones: each
// pass reads 1-3 earlier results (mostly recent ones, sometimes an old one),
// writes 1-2 (mostly new transients, sometimes a new version of an existing
// resource), about a fifth run on the async-compute queue, and the last pass
// writes the imported output.

#include <shadelgraph/graph/graph.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace sg::graph;

struct ResourceRecipe {
  std::string name;
  bool image = true;
  ImageDesc imageDesc;
  BufferDesc bufferDesc;
};

struct PassRecipe {
  std::string name;
  QueueClass queue = QueueClass::Graphics;
  PassKind kind = PassKind::Raster;
  std::vector<uint32_t> reads;   // resource indices
  std::vector<uint32_t> writes;  // resource indices
};

struct Recipe {
  std::vector<ResourceRecipe> resources;  // the last one is the imported output
  std::vector<PassRecipe> passes;
};

Recipe makeRecipe(uint32_t passCount, uint32_t seed) {
  std::mt19937 rng(seed);
  const auto chance = [&](double p) { return std::uniform_real_distribution<double>(0.0, 1.0)(rng) < p; };
  const auto below = [&](uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng); };

  Recipe recipe;
  std::vector<uint32_t> written;  // resources some earlier pass wrote, in write order
  const auto newResource = [&] {
    ResourceRecipe r;
    r.name = "r" + std::to_string(recipe.resources.size());
    r.image = chance(0.6);
    r.imageDesc = ImageDesc{.format = chance(0.5) ? Format::RGBA16F : Format::RGBA8Unorm,
                            .size = Size::relative(chance(0.7) ? 1.0f : 0.5f)};
    r.bufferDesc = BufferDesc{.size = 4096u << below(8)};
    recipe.resources.push_back(r);
    return static_cast<uint32_t>(recipe.resources.size() - 1);
  };

  for (uint32_t p = 0; p + 1 < passCount; ++p) {
    PassRecipe pass;
    pass.name = "p" + std::to_string(p);
    if (chance(0.2)) {
      pass.queue = QueueClass::AsyncCompute;
      pass.kind = PassKind::Compute;
    } else if (chance(0.15)) {
      pass.kind = PassKind::Compute;
    }
    const uint32_t readCount = written.empty() ? 0 : 1 + below(3);
    for (uint32_t i = 0; i < readCount; ++i) {
      const auto recent = static_cast<uint32_t>(std::min<std::size_t>(written.size(), 8));
      const uint32_t r = chance(0.1) ? written[below(static_cast<uint32_t>(written.size()))]
                                     : written[written.size() - 1 - below(recent)];
      if (std::find(pass.reads.begin(), pass.reads.end(), r) == pass.reads.end()) pass.reads.push_back(r);
    }
    const uint32_t writeCount = 1 + below(2);
    for (uint32_t i = 0; i < writeCount; ++i) {
      uint32_t r = newResource();
      if (!written.empty() && chance(0.3)) {  // a new version of something already written
        const uint32_t existing = written[written.size() - 1 - below(static_cast<uint32_t>(
                                                                  std::min<std::size_t>(written.size(), 8)))];
        const bool read = std::find(pass.reads.begin(), pass.reads.end(), existing) != pass.reads.end();
        const bool twice = std::find(pass.writes.begin(), pass.writes.end(), existing) != pass.writes.end();
        if (!read && !twice) {
          recipe.resources.pop_back();
          r = existing;
        }
      }
      pass.writes.push_back(r);
      written.push_back(r);
    }
    recipe.passes.push_back(pass);
  }

  // The output: imported, written by a last graphics pass reading the latest result.
  ResourceRecipe output{.name = "output", .image = true, .imageDesc = ImageDesc{.size = Size::relative(1.0f)}};
  recipe.resources.push_back(output);
  PassRecipe last{.name = "present", .reads = {}, .writes = {static_cast<uint32_t>(recipe.resources.size() - 1)}};
  if (!written.empty()) last.reads.push_back(written.back());
  recipe.passes.push_back(last);
  return recipe;
}

Access readAccess(const ResourceRecipe& r) { return r.image ? Access::Sampled : Access::StorageRead; }

Access writeAccess(const ResourceRecipe& r, PassKind kind) {
  return r.image && kind == PassKind::Raster ? Access::ColorAttachment : Access::StorageWrite;
}

void declare(RenderGraph& g, const Recipe& recipe) {
  std::vector<ResourceHandle> current;
  current.reserve(recipe.resources.size());
  for (std::size_t r = 0; r + 1 < recipe.resources.size(); ++r) {
    const ResourceRecipe& res = recipe.resources[r];
    current.push_back(res.image ? g.createImage(res.name, res.imageDesc) : g.createBuffer(res.name, res.bufferDesc));
  }
  const ResourceRecipe& out = recipe.resources.back();
  current.push_back(g.importImage(out.name, out.imageDesc, ImportedState{},
                                  FinalState{Layout::TransferSrc, PipelineStage::Transfer, AccessFlag::TransferRead}));

  for (const PassRecipe& p : recipe.passes) {
    Pass& pass = g.addPass(p.name, p.queue, p.kind);
    for (const uint32_t r : p.reads) pass.read(current[r], readAccess(recipe.resources[r]));
    for (const uint32_t r : p.writes) current[r] = pass.write(current[r], writeAccess(recipe.resources[r], p.kind));
    pass.execute([](sg::PassContext&) {});
  }
  g.markOutput(current.back());
}

CompileOptions benchOptions() {
  CompileOptions options;
  options.outputWidth = 1920;
  options.outputHeight = 1080;
  return options;
}

void BM_DeclareAndCompile(benchmark::State& state) {
  const Recipe recipe = makeRecipe(static_cast<uint32_t>(state.range(0)), 42);
  const CompileOptions options = benchOptions();
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

// Steady state of a frame loop: the same RenderGraph cleared and re-declared,
// compiled by a PlanCompiler that keeps its memory between frames.
void BM_DeclareAndCompileReusing(benchmark::State& state) {
  const Recipe recipe = makeRecipe(static_cast<uint32_t>(state.range(0)), 42);
  const CompileOptions options = benchOptions();
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
  const Recipe recipe = makeRecipe(static_cast<uint32_t>(state.range(0)), 42);
  for (auto _ : state) {
    RenderGraph g;
    declare(g, recipe);
    benchmark::DoNotOptimize(g);
  }
}

void BM_Compile(benchmark::State& state) {
  const Recipe recipe = makeRecipe(static_cast<uint32_t>(state.range(0)), 42);
  const CompileOptions options = benchOptions();
  RenderGraph g;
  declare(g, recipe);
  for (auto _ : state) {
    CompiledPlan plan = compile(g, options);
    benchmark::DoNotOptimize(plan);
  }
}

BENCHMARK(BM_DeclareAndCompile)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DeclareAndCompileReusing)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Declare)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Compile)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
