// PlanCompiler hands back its last plan when a frame declares the same graph
// again. Every test checks the plan it returns against a fresh compile of the
// same declaration, so a wrongly reused plan fails whatever the reuse flag says.
#include "plan_queries.hpp"

#include <shadelgraph/graph/graph_error.hpp>

#include <synthetic_graph.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace sg::graph {
namespace {

using test::colorImage;
using test::extent;

// A small frame: draw into a transient, blur it on the compute queue into the
// imported output. `change` edits one thing after it is declared.
struct Frame {
  uint32_t imageSide = 64;
  Access blurRead = Access::Sampled;
  std::string blurName = "blur";
  bool extraOutput = false;
};

void declareFrame(RenderGraph& g, const Frame& f) {
  ResourceHandle img = g.createImage("img", ImageDesc{.size = Size::absolute(f.imageSide, f.imageSide)});
  ResourceHandle scratch = g.createBuffer("scratch", BufferDesc{.size = 256});
  ResourceHandle out = g.importImage("out", colorImage(), ImportedState{}, FinalState{});
  Pass& draw = g.addPass("draw", QueueClass::Graphics);
  img = draw.write(img, Access::ColorAttachment);
  scratch = draw.write(scratch, Access::StorageWrite);
  Pass& blur = g.addPass(f.blurName, QueueClass::AsyncCompute);
  blur.read(img, f.blurRead);
  out = blur.write(out, Access::StorageWrite);
  g.markOutput(out);
  if (f.extraOutput) g.markOutput(scratch);
}

// Compiles `f` with `compiler` (graph cleared and declared again, as a frame
// loop does) and checks the plan against a fresh compile.
bool compileAndCheck(PlanCompiler& compiler, RenderGraph& g, const Frame& f, const CompileOptions& options = extent()) {
  g.clear();
  declareFrame(g, f);
  const CompiledPlan& plan = compiler.compile(g, options);
  RenderGraph fresh;
  declareFrame(fresh, f);
  EXPECT_EQ(toJson(plan), toJson(compile(fresh, options)));
  return compiler.reusedLastPlan();
}

TEST(PlanReuse, TheSameDeclarationGetsTheLastPlanBack) {
  PlanCompiler compiler;
  RenderGraph g;
  EXPECT_FALSE(compileAndCheck(compiler, g, {}));
  EXPECT_TRUE(compileAndCheck(compiler, g, {}));
  EXPECT_TRUE(compileAndCheck(compiler, g, {}));
}

TEST(PlanReuse, EveryChangeToTheDeclarationCompilesAgain) {
  // One change at a time, each followed by the unchanged frame again.
  const std::function<void(Frame&)> changes[] = {
      [](Frame& f) { f.imageSide = 32; },                // a resource's description
      [](Frame& f) { f.blurRead = Access::StorageRead; },  // an access
      [](Frame& f) { f.blurName = "blur2"; },              // a pass name (the plan carries it)
      [](Frame& f) { f.extraOutput = true; },              // the outputs
  };
  PlanCompiler compiler;
  RenderGraph g;
  compileAndCheck(compiler, g, {});
  for (const auto& change : changes) {
    Frame changed;
    change(changed);
    EXPECT_FALSE(compileAndCheck(compiler, g, changed));
    EXPECT_TRUE(compileAndCheck(compiler, g, changed));
    EXPECT_FALSE(compileAndCheck(compiler, g, {}));
  }
}

TEST(PlanReuse, EveryChangeToTheOptionsCompilesAgain) {
  const std::function<void(CompileOptions&)> changes[] = {
      [](CompileOptions& o) { o.outputWidth = 128; },
      [](CompileOptions& o) { o.outputHeight = 32; },
      [](CompileOptions& o) { o.enableAliasing = false; },
      [](CompileOptions& o) { o.externalWritesAreSideEffects = false; },
      [](CompileOptions& o) { o.memoryRequirements.assign(3, MemoryRequirements{.size = 4096, .alignment = 256, .memoryTypeBits = 1}); },
  };
  PlanCompiler compiler;
  RenderGraph g;
  compileAndCheck(compiler, g, {});
  for (const auto& change : changes) {
    CompileOptions changed = extent();
    change(changed);
    EXPECT_FALSE(compileAndCheck(compiler, g, {}, changed));
    EXPECT_TRUE(compileAndCheck(compiler, g, {}, changed));
    EXPECT_FALSE(compileAndCheck(compiler, g, {}));
  }
}

TEST(PlanReuse, AMemoryQueryIsNeverTrustedToAnswerTheSame) {
  // A query function cannot be compared: the requirements it gives may change.
  CompileOptions options = extent();
  options.queryMemoryRequirements = [](const ResourceDesc&) { return MemoryRequirements{.size = 1024, .alignment = 64, .memoryTypeBits = 1}; };
  PlanCompiler compiler;
  RenderGraph g;
  EXPECT_FALSE(compileAndCheck(compiler, g, {}, options));
  EXPECT_FALSE(compileAndCheck(compiler, g, {}, options));
}

TEST(PlanReuse, AFailedCompileOrATakenPlanLeavesNothingToReuse) {
  PlanCompiler compiler;
  RenderGraph g;
  compileAndCheck(compiler, g, {});
  // Reads a version of `img` nothing writes: validate throws.
  RenderGraph invalid;
  ResourceHandle img = invalid.createImage("img", colorImage());
  invalid.addPass("read", QueueClass::Graphics).sideEffect().read(ResourceHandle{img.id, 1}, Access::Sampled);
  EXPECT_THROW(compiler.compile(invalid, extent()), GraphError);
  EXPECT_FALSE(compileAndCheck(compiler, g, {}));

  const CompiledPlan taken = compiler.takePlan();
  EXPECT_FALSE(taken.order.empty());
  EXPECT_FALSE(compileAndCheck(compiler, g, {}));
  EXPECT_TRUE(compileAndCheck(compiler, g, {}));
}

TEST(PlanReuse, SyntheticGraphsInTurnGiveTheirOwnPlans) {
  // Distinct graphs of the same size through one compiler: none may get
  // another's plan; through one compiler each, every frame after the first reuses.
  const CompileOptions options = syntheticCompileOptions();
  PlanCompiler shared;
  std::vector<PlanCompiler> own(4);
  std::vector<RenderGraph> graphs(4);
  for (int frame = 0; frame < 2; ++frame) {
    for (uint32_t i = 0; i < 4; ++i) {
      const SyntheticGraph recipe = makeSyntheticGraph(60, 7 + i);
      graphs[i].clear();
      declare(graphs[i], recipe);
      RenderGraph fresh;
      declare(fresh, recipe);
      const std::string expected = toJson(compile(fresh, options));
      EXPECT_EQ(toJson(shared.compile(graphs[i], options)), expected);
      EXPECT_FALSE(shared.reusedLastPlan());
      EXPECT_EQ(toJson(own[i].compile(graphs[i], options)), expected);
      EXPECT_EQ(own[i].reusedLastPlan(), frame > 0);
    }
  }
}

}  // namespace
}  // namespace sg::graph
