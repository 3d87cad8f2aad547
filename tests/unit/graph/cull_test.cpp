#include "plan_queries.hpp"

#include <shadelgraph/graph/cull.hpp>

#include <gtest/gtest.h>

namespace sg::graph {
namespace {

using test::colorImage;
using test::extent;
using test::orderNames;
using test::passNamed;

TEST(GraphCull, ChainNobodyReadsIsCulledTransitively) {
  RenderGraph g;
  auto a = g.createImage("a", colorImage());
  auto b = g.createImage("b", colorImage());
  auto c = g.createImage("c", colorImage());
  auto out = g.importImage("output", colorImage(), ImportedState{}, FinalState{.layout = Layout::ColorAttachment});
  auto& p1 = g.addPass("p1", QueueClass::Graphics);
  a = p1.write(a, Access::ColorAttachment);
  auto& p2 = g.addPass("p2", QueueClass::Graphics);
  p2.read(a, Access::Sampled);
  b = p2.write(b, Access::ColorAttachment);
  auto& p3 = g.addPass("p3", QueueClass::Graphics);
  p3.read(b, Access::Sampled);
  (void)p3.write(c, Access::ColorAttachment);  // nobody reads c
  (void)g.addPass("present", QueueClass::Graphics).write(out, Access::ColorAttachment);

  const std::vector<bool> culled = cullPasses(g, indexVersions(g));
  EXPECT_EQ(culled, (std::vector<bool>{true, true, true, false}));

  const CompiledPlan plan = compile(g, extent());
  EXPECT_EQ(orderNames(plan), std::vector<std::string>{"present"});
  EXPECT_TRUE(plan.resources[a.id.index].culled);
  EXPECT_FALSE(plan.resources[a.id.index].memory.placed());  // culled transients get no memory
}

TEST(GraphCull, SideEffectPassKeepsItsInputs) {
  RenderGraph g;
  auto counters = g.createBuffer("counters", BufferDesc{.size = 64});
  auto unused = g.createBuffer("unused", BufferDesc{.size = 64});
  auto& count = g.addPass("count", QueueClass::AsyncCompute);
  counters = count.write(counters, Access::StorageWrite);
  (void)g.addPass("dead", QueueClass::AsyncCompute).write(unused, Access::StorageWrite);
  auto& readback = g.addPass("readback", QueueClass::Transfer);
  readback.read(counters, Access::TransferSrc);
  readback.sideEffect();

  const CompiledPlan plan = compile(g, extent());
  EXPECT_FALSE(passNamed(plan, "count").culled);
  EXPECT_FALSE(passNamed(plan, "readback").culled);
  EXPECT_TRUE(passNamed(plan, "dead").culled);
  EXPECT_EQ(orderNames(plan), (std::vector<std::string>{"count", "readback"}));
}

TEST(GraphCull, WritingAnImportCountsAsSideEffectUnlessConfiguredOff) {
  RenderGraph g;
  auto stats = g.importBuffer("stats", BufferDesc{.size = 16}, ImportedState{}, FinalState{});
  (void)g.addPass("stats", QueueClass::AsyncCompute).write(stats, Access::StorageWrite);

  EXPECT_EQ(cullPasses(g, indexVersions(g), true), std::vector<bool>{false});
  EXPECT_EQ(cullPasses(g, indexVersions(g), false), std::vector<bool>{true});
}

// The roots come from the per-pass kinds indexVersions() gathers: writing a
// persistent resource is a root like writing an import; reading one is not.
TEST(GraphCull, PassKindsMakeWritersOfPersistentResourcesRootsAndReadersNot) {
  RenderGraph g;
  auto accum = g.importPersistentImage("accum", colorImage(), ResourceState{.stages = PipelineStage::AllCommands});
  auto scratch = g.createImage("scratch", colorImage());
  auto& reader = g.addPass("reader", QueueClass::Graphics);
  reader.read(accum, Access::Sampled);
  (void)reader.write(scratch, Access::ColorAttachment);
  (void)g.addPass("writer", QueueClass::AsyncCompute).write(accum, Access::StorageWrite);

  const VersionTable versions = indexVersions(g);
  ASSERT_EQ(versions.passKinds.size(), 2u);
  EXPECT_EQ(versions.passKinds[0].accessed,
            kindBit(ResourceKind::Persistent) | kindBit(ResourceKind::TransientImage));
  EXPECT_EQ(versions.passKinds[0].written, kindBit(ResourceKind::TransientImage));
  EXPECT_EQ(versions.passKinds[1].accessed, kindBit(ResourceKind::Persistent));
  EXPECT_EQ(versions.passKinds[1].written, kindBit(ResourceKind::Persistent));
  // The writer reads nothing the reader produces, so only the writer is kept.
  EXPECT_EQ(cullPasses(g, versions, true), (std::vector<bool>{true, false}));
  EXPECT_EQ(cullPasses(g, versions, false), (std::vector<bool>{true, true}));
}

TEST(GraphCull, OutputKeepsOnlyTheProducerOfTheMarkedVersion) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& draw = g.addPass("draw", QueueClass::Graphics);
  const ResourceHandle v1 = draw.write(img, Access::ColorAttachment);
  auto& overlay = g.addPass("overlay", QueueClass::Graphics);
  overlay.read(v1, Access::ColorAttachmentRead);
  (void)overlay.write(v1, Access::ColorAttachment);
  g.markOutput(v1);  // the version before the overlay

  const CompiledPlan plan = compile(g, extent());
  EXPECT_FALSE(passNamed(plan, "draw").culled);
  EXPECT_TRUE(passNamed(plan, "overlay").culled);
}

// Passes may be declared before the producers they read from (handles are
// wired after adding the passes): the producers are still kept, transitively.
TEST(GraphCull, ProducersDeclaredAfterTheirReadersAreKept) {
  RenderGraph g;
  auto a = g.createImage("a", colorImage());
  auto b = g.createImage("b", colorImage());
  auto c = g.createImage("c", colorImage());
  auto out = g.importImage("output", colorImage(), ImportedState{}, FinalState{.layout = Layout::ColorAttachment});
  auto& present = g.addPass("present", QueueClass::Graphics);
  auto& second = g.addPass("second", QueueClass::Graphics);
  auto& first = g.addPass("first", QueueClass::Graphics);
  (void)g.addPass("unused", QueueClass::Graphics).write(c, Access::ColorAttachment);
  a = first.write(a, Access::ColorAttachment);
  second.read(a, Access::Sampled);
  b = second.write(b, Access::ColorAttachment);
  present.read(b, Access::Sampled);
  (void)present.write(out, Access::ColorAttachment);

  EXPECT_EQ(cullPasses(g, indexVersions(g)), (std::vector<bool>{false, false, false, true}));
}

TEST(GraphCull, CulledPassesStayInThePlanWithoutBatchOrBarriers) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& orphan = g.addPass("orphan", QueueClass::Graphics);
  (void)orphan.write(img, Access::ColorAttachment);
  g.addPass("kept", QueueClass::Graphics).sideEffect();

  const CompiledPlan plan = compile(g, extent());
  ASSERT_EQ(plan.passes.size(), 2u);
  const PlannedPass& culled = passNamed(plan, "orphan");
  EXPECT_TRUE(culled.culled);
  EXPECT_EQ(culled.batch, kInvalidIndex);
  EXPECT_EQ(culled.orderIndex, kInvalidIndex);
  EXPECT_EQ(culled.barriersBefore.count, 0u);
  EXPECT_EQ(plan.accessesOf(test::idOf(plan, "orphan")).size(), 1u);  // declared accesses are still listed
}

}  // namespace
}  // namespace sg::graph
