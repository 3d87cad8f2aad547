#include "plan_queries.hpp"

#include <shadelgraph/graph/cull.hpp>
#include <shadelgraph/graph/order.hpp>
#include <shadelgraph/graph/plan_barriers.hpp>
#include <shadelgraph/graph/plan_resources.hpp>

#include <gtest/gtest.h>

namespace sg::graph {
namespace {

using test::barriersBefore;
using test::barriersAfter;
using test::waitsBefore;
using test::colorImage;
using test::extent;

using S = PipelineStage;
using A = AccessFlag;

TEST(GraphBarriers, ReadAfterReadNeedsNone) {
  RenderGraph g;
  auto lut = g.importImage("lut", colorImage(), ImportedState{Layout::ShaderReadOnly, S::FragmentShader, A::ShaderSampledRead},
                           FinalState{.layout = Layout::ShaderReadOnly}, ImportMode::ReadOnly);
  g.addPass("r1", QueueClass::Graphics).sideEffect().read(lut, Access::Sampled);
  g.addPass("r2", QueueClass::Graphics).sideEffect().read(lut, Access::Sampled);
  const CompiledPlan plan = compile(g, extent());
  EXPECT_TRUE(barriersBefore(plan, "r1", lut).empty());
  EXPECT_TRUE(barriersBefore(plan, "r2", lut).empty());
  EXPECT_TRUE(plan.finalBarriers.empty());
}

TEST(GraphBarriers, WriteAfterWriteGetsOne) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 64});
  auto& w1 = g.addPass("w1", QueueClass::Graphics, PassKind::Compute);
  auto v1 = w1.write(buf, Access::StorageWrite);
  auto& w2 = g.addPass("w2", QueueClass::Graphics, PassKind::Compute);
  g.markOutput(w2.write(v1, Access::StorageWrite));
  const CompiledPlan plan = compile(g, extent());
  EXPECT_TRUE(barriersBefore(plan, "w1", buf).empty());  // a transient buffer's first use
  const Barrier expected{.resource = buf.id,
                         .srcStages = S::ComputeShader,
                         .dstStages = S::ComputeShader,
                         .srcAccess = A::ShaderStorageWrite,
                         .dstAccess = A::ShaderStorageWrite};
  EXPECT_EQ(barriersBefore(plan, "w2", buf), std::vector<Barrier>{expected});
}

TEST(GraphBarriers, WriteAfterReadIsExecutionOnly) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 64});
  auto& w1 = g.addPass("w1", QueueClass::Graphics, PassKind::Compute);
  auto v1 = w1.write(buf, Access::StorageWrite);
  g.addPass("read", QueueClass::Graphics, PassKind::Compute).sideEffect().read(v1, Access::StorageRead);
  auto& w2 = g.addPass("w2", QueueClass::Graphics, PassKind::Compute);
  g.markOutput(w2.write(v1, Access::StorageWrite));
  const CompiledPlan plan = compile(g, extent());

  const Barrier raw{.resource = buf.id,
                    .srcStages = S::ComputeShader,
                    .dstStages = S::ComputeShader,
                    .srcAccess = A::ShaderStorageWrite,
                    .dstAccess = A::ShaderStorageRead};
  EXPECT_EQ(barriersBefore(plan, "read", buf), std::vector<Barrier>{raw});
  // The first write was made available before the read: only execution order remains.
  const Barrier war{.resource = buf.id,
                    .srcStages = S::ComputeShader,
                    .dstStages = S::ComputeShader,
                    .srcAccess = A::None,
                    .dstAccess = A::ShaderStorageWrite};
  EXPECT_EQ(barriersBefore(plan, "w2", buf), std::vector<Barrier>{war});
}

TEST(GraphBarriers, ColorAttachmentToSampledTransitionsTheLayout) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& draw = g.addPass("draw", QueueClass::Graphics);
  img = draw.write(img, Access::ColorAttachment);
  g.addPass("sample", QueueClass::Graphics).sideEffect().read(img, Access::Sampled);
  const CompiledPlan plan = compile(g, extent());

  const Barrier first{.resource = img.id,
                      .srcStages = S::None,
                      .dstStages = S::ColorAttachmentOutput,
                      .srcAccess = A::None,
                      .dstAccess = A::ColorAttachmentWrite,
                      .oldLayout = Layout::Undefined,
                      .newLayout = Layout::ColorAttachment,
                      .discard = true};
  EXPECT_EQ(barriersBefore(plan, "draw", img), std::vector<Barrier>{first});
  const Barrier toSampled{.resource = img.id,
                          .srcStages = S::ColorAttachmentOutput,
                          .dstStages = S::FragmentShader,
                          .srcAccess = A::ColorAttachmentWrite,
                          .dstAccess = A::ShaderSampledRead,
                          .oldLayout = Layout::ColorAttachment,
                          .newLayout = Layout::ShaderReadOnly};
  EXPECT_EQ(barriersBefore(plan, "sample", img), std::vector<Barrier>{toSampled});
}

TEST(GraphBarriers, ConsecutiveReadersShareOneBarrier) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& write = g.addPass("write", QueueClass::Graphics, PassKind::Compute);
  img = write.write(img, Access::StorageWrite);
  g.addPass("fragment", QueueClass::Graphics).sideEffect().read(img, Access::Sampled);
  g.addPass("compute", QueueClass::Graphics, PassKind::Compute).sideEffect().read(img, Access::Sampled);
  const CompiledPlan plan = compile(g, extent());

  const std::vector<Barrier> shared = barriersBefore(plan, "fragment", img);
  ASSERT_EQ(shared.size(), 1u);
  EXPECT_EQ(shared[0].dstStages, S::FragmentShader | S::ComputeShader);
  EXPECT_EQ(shared[0].oldLayout, Layout::General);
  EXPECT_EQ(shared[0].newLayout, Layout::ShaderReadOnly);
  EXPECT_TRUE(barriersBefore(plan, "compute", img).empty());
}

TEST(GraphBarriers, LayoutChangeBetweenTwoReadsNeedsOne) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& draw = g.addPass("draw", QueueClass::Graphics);
  img = draw.write(img, Access::ColorAttachment);
  g.addPass("sample", QueueClass::Graphics).sideEffect().read(img, Access::Sampled);
  g.addPass("copy", QueueClass::Graphics, PassKind::Transfer).sideEffect().read(img, Access::TransferSrc);
  const CompiledPlan plan = compile(g, extent());

  ASSERT_EQ(barriersBefore(plan, "sample", img).size(), 1u);
  EXPECT_EQ(barriersBefore(plan, "sample", img)[0].dstStages, S::FragmentShader);  // not the copy's stage
  const Barrier toCopy{.resource = img.id,
                       .srcStages = S::FragmentShader,  // after the sampling, which followed the write
                       .dstStages = S::Transfer,
                       .srcAccess = A::None,
                       .dstAccess = A::TransferRead,
                       .oldLayout = Layout::ShaderReadOnly,
                       .newLayout = Layout::TransferSrc};
  EXPECT_EQ(barriersBefore(plan, "copy", img), std::vector<Barrier>{toCopy});
}

// The pass's two accesses to depth merge into one use, even with another
// resource's access declared between them.
TEST(GraphBarriers, DepthTestAndSamplingShareTheReadOnlyDepthLayout) {
  RenderGraph g;
  auto depth = g.createImage("depth", ImageDesc{.format = Format::D32F, .size = Size::absolute(8, 8)});
  auto color = g.createImage("color", colorImage());
  auto& prepass = g.addPass("prepass", QueueClass::Graphics);
  depth = prepass.write(depth, Access::DepthAttachment);
  color = prepass.write(color, Access::ColorAttachment);
  auto& shade = g.addPass("shade", QueueClass::Graphics);
  shade.read(depth, Access::DepthRead);
  shade.read(color, Access::Sampled);
  shade.read(depth, Access::Sampled);
  shade.sideEffect();
  const CompiledPlan plan = compile(g, extent());

  const Barrier expectedDepth{.resource = depth.id,
                              .srcStages = S::EarlyFragmentTests | S::LateFragmentTests,
                              .dstStages = S::EarlyFragmentTests | S::LateFragmentTests | S::FragmentShader,
                              .srcAccess = A::DepthStencilWrite,
                              .dstAccess = A::DepthStencilRead | A::ShaderSampledRead,
                              .oldLayout = Layout::DepthAttachment,
                              .newLayout = Layout::DepthReadOnly};
  EXPECT_EQ(barriersBefore(plan, "shade", depth), std::vector<Barrier>{expectedDepth});
  const Barrier expectedColor{.resource = color.id,
                              .srcStages = S::ColorAttachmentOutput,
                              .dstStages = S::FragmentShader,
                              .srcAccess = A::ColorAttachmentWrite,
                              .dstAccess = A::ShaderSampledRead,
                              .oldLayout = Layout::ColorAttachment,
                              .newLayout = Layout::ShaderReadOnly};
  EXPECT_EQ(barriersBefore(plan, "shade", color), std::vector<Barrier>{expectedColor});
}

TEST(GraphBarriers, ImportStartsInItsInitialStateAndEndsInItsFinalState) {
  RenderGraph g;
  auto out = g.importImage("output", colorImage(), ImportedState{},
                           FinalState{Layout::TransferSrc, S::Transfer, A::TransferRead});
  auto& draw = g.addPass("draw", QueueClass::Graphics);
  g.markOutput(draw.write(out, Access::ColorAttachment));
  const CompiledPlan plan = compile(g, extent());

  const std::vector<Barrier> first = barriersBefore(plan, "draw", out);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].oldLayout, Layout::Undefined);
  EXPECT_TRUE(first[0].discard);

  ASSERT_EQ(plan.finalBarriers.size(), 1u);
  const FinalBarrier& final = plan.finalBarriers[0];
  const Barrier expected{.resource = out.id,
                         .srcStages = S::ColorAttachmentOutput,
                         .dstStages = S::Transfer,
                         .srcAccess = A::ColorAttachmentWrite,
                         .dstAccess = A::TransferRead,
                         .oldLayout = Layout::ColorAttachment,
                         .newLayout = Layout::TransferSrc};
  EXPECT_EQ(final.barrier, expected);
  EXPECT_EQ(final.afterPass, PassId{0});
  EXPECT_EQ(final.batch, 0u);
}

TEST(GraphBarriers, InitialStateOfAnImportIsTheSource) {
  RenderGraph g;
  auto prev = g.importImage("prev", colorImage(), ImportedState{Layout::General, S::ComputeShader, A::ShaderStorageWrite},
                            FinalState{.layout = Layout::ShaderReadOnly});
  g.addPass("sample", QueueClass::Graphics).sideEffect().read(prev, Access::Sampled);
  const CompiledPlan plan = compile(g, extent());
  const Barrier expected{.resource = prev.id,
                         .srcStages = S::ComputeShader,
                         .dstStages = S::FragmentShader,
                         .srcAccess = A::ShaderStorageWrite,
                         .dstAccess = A::ShaderSampledRead,
                         .oldLayout = Layout::General,
                         .newLayout = Layout::ShaderReadOnly};
  EXPECT_EQ(barriersBefore(plan, "sample", prev), std::vector<Barrier>{expected});
  EXPECT_TRUE(plan.finalBarriers.empty());  // already in its final layout
}

TEST(GraphBarriers, AcrossQueuesOnlyTheLayoutTransitionRemains) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& draw = g.addPass("draw", QueueClass::Graphics);
  img = draw.write(img, Access::ColorAttachment);
  g.addPass("blur", QueueClass::AsyncCompute).sideEffect().read(img, Access::Sampled);
  const CompiledPlan plan = compile(g, extent());

  // The semaphore wait carries the memory dependency; the barrier chains on its stage.
  const Barrier expected{.resource = img.id,
                         .srcStages = S::ComputeShader,
                         .dstStages = S::ComputeShader,
                         .srcAccess = A::None,
                         .dstAccess = A::ShaderSampledRead,
                         .oldLayout = Layout::ColorAttachment,
                         .newLayout = Layout::ShaderReadOnly};
  EXPECT_EQ(barriersBefore(plan, "blur", img), std::vector<Barrier>{expected});
  EXPECT_EQ(waitsBefore(plan, "blur"), (std::vector<SemaphoreWait>{{QueueClass::Graphics, 1, S::ComputeShader}}));
  EXPECT_TRUE(barriersAfter(plan, "draw").empty());
}

TEST(GraphBarriers, VersionReadOnTwoQueuesIsTransitionedOnceByTheProducer) {
  RenderGraph g;
  auto hdr = g.createImage("hdr", colorImage());
  auto& scene = g.addPass("scene", QueueClass::Graphics);
  hdr = scene.write(hdr, Access::ColorAttachment);
  g.addPass("luminance", QueueClass::AsyncCompute).sideEffect().read(hdr, Access::Sampled);
  g.addPass("tonemap", QueueClass::Graphics).sideEffect().read(hdr, Access::Sampled);
  const CompiledPlan plan = compile(g, extent());

  const Barrier handOff{.resource = hdr.id,
                        .srcStages = S::ColorAttachmentOutput,
                        .dstStages = S::FragmentShader,  // the reader on this queue
                        .srcAccess = A::ColorAttachmentWrite,
                        .dstAccess = A::ShaderSampledRead,
                        .oldLayout = Layout::ColorAttachment,
                        .newLayout = Layout::ShaderReadOnly};
  EXPECT_EQ(barriersAfter(plan, "scene"), std::vector<Barrier>{handOff});
  EXPECT_TRUE(barriersBefore(plan, "luminance", hdr).empty());
  EXPECT_TRUE(barriersBefore(plan, "tonemap", hdr).empty());
}

TEST(GraphBarriers, FrameStartVersionReadOnTwoQueuesHandsOffTheTransition) {
  RenderGraph g;
  auto table = g.importImage("table", colorImage(), ImportedState{Layout::General, S::AllCommands, A::None},
                             FinalState{.layout = Layout::ShaderReadOnly}, ImportMode::ReadOnly);
  g.addPass("first", QueueClass::Graphics).sideEffect().read(table, Access::Sampled);
  g.addPass("second", QueueClass::AsyncCompute).sideEffect().read(table, Access::Sampled);
  const CompiledPlan plan = compile(g, extent());

  const std::vector<Barrier> transition = barriersBefore(plan, "first", table);
  ASSERT_EQ(transition.size(), 1u);
  EXPECT_EQ(transition[0].srcStages, S::AllCommands);
  EXPECT_EQ(transition[0].oldLayout, Layout::General);
  EXPECT_EQ(transition[0].newLayout, Layout::ShaderReadOnly);
  EXPECT_TRUE(barriersBefore(plan, "second", table).empty());
  // The other queue's reader waits for the transition.
  EXPECT_EQ(waitsBefore(plan, "second"), (std::vector<SemaphoreWait>{{QueueClass::Graphics, 1, S::ComputeShader}}));
}

TEST(GraphBarriers, UsageIsTheUnionOfAccesses) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto args = g.createBuffer("args", BufferDesc{.size = 64});
  auto& draw = g.addPass("draw", QueueClass::Graphics);
  img = draw.write(img, Access::ColorAttachment);
  args = draw.write(args, Access::StorageWrite);
  auto& use = g.addPass("use", QueueClass::Graphics);
  use.read(img, Access::Sampled);
  use.read(args, Access::IndirectArgs);
  use.sideEffect();
  g.addPass("copy", QueueClass::Graphics, PassKind::Transfer).sideEffect().read(img, Access::TransferSrc);
  const CompiledPlan plan = compile(g, extent());
  EXPECT_EQ(plan.resources[img.id.index].desc.imageUsage,
            ImageUsage::ColorAttachment | ImageUsage::Sampled | ImageUsage::TransferSrc);
  EXPECT_EQ(plan.resources[args.id.index].desc.bufferUsage, BufferUsage::Storage | BufferUsage::Indirect);
  EXPECT_EQ(plan.resources[args.id.index].desc.imageUsage, ImageUsage::None);
}

TEST(GraphBarriers, PlanBarriersRunsOnPlainData) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 64});
  auto& w1 = g.addPass("w1", QueueClass::Graphics, PassKind::Compute);
  auto& w2 = g.addPass("w2", QueueClass::Graphics, PassKind::Compute);
  g.markOutput(w2.write(w1.write(buf, Access::StorageWrite), Access::StorageWrite));
  const std::vector<PassId> order{PassId{0}, PassId{1}};
  const std::vector<PlannedResource> resources = planResources(g, order, 64, 64);
  const BarrierPlan barriers = planBarriers(g, order, resources, {});
  EXPECT_TRUE(barriers.beforePass(PassId{0}).empty());
  ASSERT_EQ(barriers.beforePass(PassId{1}).size(), 1u);
  EXPECT_EQ(barriers.beforePass(PassId{1})[0].srcAccess, A::ShaderStorageWrite);
  EXPECT_TRUE(barriers.finals.empty());
  EXPECT_TRUE(barriers.handoffs.empty());
}

// placeTransients lays alias lists back to back in resource order, which
// planBarriers walks as one flat list; lists in any other layout give the same barriers.
TEST(GraphBarriers, AliasListsInAnyLayoutGiveTheSameTakeOver) {
  RenderGraph g;
  auto a = g.createBuffer("a", BufferDesc{.size = 64});
  auto b = g.createBuffer("b", BufferDesc{.size = 64});
  auto& p0 = g.addPass("p0", QueueClass::Graphics, PassKind::Compute);
  a = p0.write(a, Access::StorageWrite);
  auto& p1 = g.addPass("p1", QueueClass::Graphics, PassKind::Compute);
  p1.read(a, Access::StorageRead);
  b = p1.write(b, Access::StorageWrite);
  g.markOutput(b);
  auto& p2 = g.addPass("p2", QueueClass::Graphics, PassKind::Compute);
  g.markOutput(p2.write(g.createBuffer("c", BufferDesc{.size = 64}), Access::StorageWrite));
  const std::vector<PassId> order{PassId{0}, PassId{1}, PassId{2}};
  std::vector<PlannedResource> resources = planResources(g, order, 64, 64);
  ASSERT_EQ(resources.size(), 3u);
  const ResourceId c{2};
  // c takes over a's memory (a is used before c), and a lists c as its successor.
  const Barrier expected{.resource = c,
                         .srcStages = S::ComputeShader,
                         .dstStages = S::ComputeShader,
                         .srcAccess = A::ShaderStorageWrite,
                         .dstAccess = A::ShaderStorageWrite,
                         .discard = true};
  resources[a.id.index].aliasesWith = {0, 1};
  resources[b.id.index].aliasesWith = {1, 0};
  resources[c.index].aliasesWith = {1, 1};
  const std::vector<ResourceId> backToBack{c, a.id};
  const BarrierPlan inOrder = planBarriers(g, order, resources, backToBack);
  ASSERT_EQ(inOrder.beforePass(PassId{2}).size(), 1u);
  EXPECT_EQ(inOrder.beforePass(PassId{2})[0], expected);
  resources[a.id.index].aliasesWith = {1, 1};
  resources[c.index].aliasesWith = {0, 1};
  const std::vector<ResourceId> swapped{a.id, c};
  const BarrierPlan outOfOrder = planBarriers(g, order, resources, swapped);
  EXPECT_EQ(outOfOrder.barriers, inOrder.barriers);
  EXPECT_TRUE(inOrder.beforePass(PassId{0}).empty());  // a took over nobody's memory
}

}  // namespace
}  // namespace sg::graph
