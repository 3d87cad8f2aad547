#include "plan_queries.hpp"

#include <shadelgraph/graph/validate.hpp>

#include <gtest/gtest.h>

#include <utility>

namespace sg::graph {
namespace {

using test::colorImage;
using test::extent;
using test::orderNames;
using test::toVector;

TEST(GraphDeclare, WriteReturnsTheNextVersionAndReadsNameOne) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& pass = g.addPass("draw", QueueClass::Graphics);
  const ResourceHandle v1 = pass.write(img, Access::ColorAttachment);
  EXPECT_EQ(v1, (ResourceHandle{img.id, 1}));
  EXPECT_EQ(pass.write(img, Access::ColorAttachment), v1);  // same pass, same handle: same version
  ASSERT_EQ(pass.accesses().size(), 2u);
  EXPECT_EQ(pass.accesses()[0].version, 0u);
  EXPECT_TRUE(pass.accesses()[0].write);
  EXPECT_EQ(pass.accesses()[0].stages, PipelineStage::ColorAttachmentOutput);
}

TEST(GraphDeclare, InterleavedPassesKeepTheirOwnAccesses) {
  RenderGraph g;
  auto a = g.createBuffer("a", BufferDesc{.size = 4});
  auto b = g.createBuffer("b", BufferDesc{.size = 4});
  auto& first = g.addPass("first", QueueClass::AsyncCompute);
  auto& second = g.addPass("second", QueueClass::AsyncCompute);
  a = first.write(a, Access::StorageWrite);
  b = second.write(b, Access::StorageWrite);
  second.read(a, Access::StorageRead);
  first.sideEffect().read(b, Access::StorageRead);  // first is declared again after second

  ASSERT_EQ(first.accesses().size(), 2u);
  EXPECT_EQ(first.accesses()[0].resource, a.id);
  EXPECT_EQ(first.accesses()[1].resource, b.id);
  ASSERT_EQ(second.accesses().size(), 2u);
  EXPECT_EQ(second.accesses()[0].resource, b.id);
  EXPECT_EQ(second.accesses()[1].resource, a.id);
  // first reads what second writes and the other way round: a cycle, named.
  const std::vector<ValidationError> errors = validate(g, extent());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].message.find("cycle"), std::string::npos);
}

TEST(GraphDeclare, HistoryIsDeclaredOncePerPersistentResource) {
  RenderGraph g;
  auto layer = g.importPersistentBuffer("layer", BufferDesc{.size = 64},
                                        ResourceState{.stages = PipelineStage::AllCommands});
  const ResourceHandle first = g.history(layer);
  EXPECT_EQ(g.history(layer), first);
  EXPECT_EQ(g.resourceCount(), 2u);
  EXPECT_EQ(g.resource(first.id).kind, ResourceKind::History);
  EXPECT_TRUE(g.resource(first.id).readOnly);
}

TEST(GraphDeclare, PassCallbackIsKeptForTheExecutor) {
  RenderGraph g;
  int calls = 0;
  g.addPass("p", QueueClass::Graphics).sideEffect().execute([&calls](sg::PassContext&) { ++calls; });
  EXPECT_TRUE(static_cast<bool>(g.callback(PassId{0})));
  EXPECT_EQ(g.passName(PassId{0}), "p");
  EXPECT_EQ(calls, 0);  // never called by the graph
}

// A two-pass frame; `suffix` varies the names so reuse has to overwrite them.
void declareFrame(RenderGraph& g, const std::string& suffix) {
  auto img = g.createImage("img" + suffix, colorImage());
  auto& draw = g.addPass("draw" + suffix, QueueClass::Graphics);
  img = draw.write(img, Access::ColorAttachment);
  g.addPass("blur" + suffix, QueueClass::AsyncCompute).sideEffect().read(img, Access::Sampled);
}

TEST(GraphDeclare, ClearedGraphAndPlanCompilerGiveWhatFreshOnesGive) {
  RenderGraph reused;
  PlanCompiler compiler;
  for (const std::string suffix : {"", "-second-frame-with-a-long-name"}) {
    reused.clear();
    declareFrame(reused, suffix);
    RenderGraph fresh;
    declareFrame(fresh, suffix);

    const CompiledPlan& again = compiler.compile(reused, extent());
    const CompiledPlan once = compile(fresh, extent());
    EXPECT_EQ(orderNames(again), orderNames(once));
    EXPECT_EQ(toVector(again.barriersBefore(PassId{1})), toVector(once.barriersBefore(PassId{1})));
    EXPECT_EQ(toVector(again.waitsOf(again.batches.back())), toVector(once.waitsOf(once.batches.back())));
    EXPECT_EQ(again.resources[0].name, "img" + suffix);
    EXPECT_EQ(toJson(again), toJson(once));
  }
}

TEST(GraphDeclare, ResourceTraitsFollowTheDeclarations) {
  // The compact per-resource traits the compile steps look up must match the
  // declarations, history resources included, and be cleared with the graph.
  RenderGraph g;
  g.createImage("color", colorImage());
  g.importBuffer("readback", BufferDesc{.size = 256}, ImportedState{}, FinalState{}, ImportMode::ReadOnly);
  const ResourceHandle persistent = g.importPersistentImage("accum", colorImage(), ResourceState{});
  g.history(persistent);
  const GraphDeclaration& d = g.declaration();
  ASSERT_EQ(d.traits.size(), d.resources.size());
  for (std::size_t r = 0; r < d.resources.size(); ++r) {
    EXPECT_EQ(d.traits[r].kind, d.resources[r].kind);
    EXPECT_EQ(d.traits[r].type, d.resources[r].type);
    EXPECT_EQ(d.traits[r].readOnly, d.resources[r].readOnly);
    if (d.resources[r].type == ResourceType::Image) {
      EXPECT_EQ(d.traits[r].format, d.resources[r].image.format);
    }
  }
  EXPECT_TRUE(d.traits[1].readOnly);
  EXPECT_EQ(d.traits[3].kind, ResourceKind::History);
  g.clear();
  EXPECT_TRUE(g.declaration().traits.empty());
}

TEST(GraphDeclare, MovedGraphKeepsItsPassBuildersWorking) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 4});
  auto& pass = g.addPass("fill", QueueClass::AsyncCompute);
  RenderGraph moved = std::move(g);
  moved.markOutput(pass.write(buf, Access::StorageWrite));  // the builder still writes into `moved`
  EXPECT_EQ(moved.accessesOf(PassId{0}).size(), 1u);
  EXPECT_EQ(orderNames(compile(moved, extent())), std::vector<std::string>{"fill"});
}

}  // namespace
}  // namespace sg::graph
