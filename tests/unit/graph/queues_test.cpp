#include "plan_queries.hpp"

#include <shadelgraph/graph/assign_queues.hpp>

#include <gtest/gtest.h>

namespace sg::graph {
namespace {

using test::batchOf;
using test::toVector;
using test::waitsBefore;
using test::colorImage;
using test::extent;

// scene (graphics) -> luminance (async compute) -> tonemap (graphics)
struct LuminanceGraph {
  RenderGraph g;
  ResourceHandle hdr, lum, out;

  LuminanceGraph() {
    hdr = g.createImage("hdr", ImageDesc{.format = Format::RGBA16F, .size = Size::relative(1.0f)});
    lum = g.createBuffer("luminance", BufferDesc{.size = 256});
    out = g.importImage("output", colorImage(), ImportedState{},
                        FinalState{Layout::TransferSrc, PipelineStage::Transfer, AccessFlag::TransferRead});
    auto& scene = g.addPass("scene", QueueClass::Graphics);
    hdr = scene.write(hdr, Access::ColorAttachment);
    auto& avg = g.addPass("luminance", QueueClass::AsyncCompute);
    avg.read(hdr, Access::Sampled);
    lum = avg.write(lum, Access::StorageWrite);
    auto& tonemap = g.addPass("tonemap", QueueClass::Graphics);
    tonemap.read(hdr, Access::Sampled);
    tonemap.read(lum, Access::StorageRead);
    out = tonemap.write(out, Access::ColorAttachment);
    g.markOutput(out);
  }
};

TEST(GraphQueues, AsyncComputeBetweenTwoGraphicsPasses) {
  const LuminanceGraph graph;
  const CompiledPlan plan = compile(graph.g, extent());
  ASSERT_EQ(plan.batches.size(), 3u);

  const Batch& first = plan.batches[0];
  EXPECT_EQ(first.queue, QueueClass::Graphics);
  EXPECT_EQ(toVector(plan.passesOf(first)), std::vector<PassId>{PassId{0}});
  EXPECT_TRUE(plan.waitsOf(first).empty());
  EXPECT_EQ(first.signalValue, 1u);

  const Batch& compute = plan.batches[1];
  EXPECT_EQ(compute.queue, QueueClass::AsyncCompute);
  EXPECT_EQ(toVector(plan.passesOf(compute)), std::vector<PassId>{PassId{1}});
  EXPECT_EQ(toVector(plan.waitsOf(compute)),
            (std::vector<SemaphoreWait>{{QueueClass::Graphics, 1, PipelineStage::ComputeShader}}));
  EXPECT_EQ(compute.signalValue, 1u);

  const Batch& last = plan.batches[2];
  EXPECT_EQ(last.queue, QueueClass::Graphics);
  EXPECT_EQ(toVector(plan.passesOf(last)), std::vector<PassId>{PassId{2}});
  EXPECT_EQ(toVector(plan.waitsOf(last)),
            (std::vector<SemaphoreWait>{{QueueClass::AsyncCompute, 1, PipelineStage::FragmentShader}}));
  EXPECT_EQ(last.signalValue, 0u);  // nobody waits on the last batch
}

TEST(GraphQueues, SingleQueueHasOneBatchAndNoSemaphores) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& a = g.addPass("a", QueueClass::Graphics);
  img = a.write(img, Access::ColorAttachment);
  auto& b = g.addPass("b", QueueClass::Graphics);
  b.read(img, Access::Sampled);
  b.sideEffect();
  const CompiledPlan plan = compile(g, extent());
  ASSERT_EQ(plan.batches.size(), 1u);
  EXPECT_EQ(plan.passesOf(plan.batches[0]).size(), 2u);
  EXPECT_TRUE(plan.waitsOf(plan.batches[0]).empty());
  EXPECT_EQ(plan.batches[0].signalValue, 0u);
}

TEST(GraphQueues, WaitAlreadyDoneByAnEarlierBatchOnTheQueueIsSkipped) {
  RenderGraph g;
  auto x = g.createBuffer("x", BufferDesc{.size = 16});
  auto y = g.createBuffer("y", BufferDesc{.size = 16});
  auto& produce = g.addPass("produce", QueueClass::AsyncCompute);
  x = produce.write(x, Access::StorageWrite);
  auto& first = g.addPass("first", QueueClass::Graphics);
  first.read(x, Access::StorageRead);
  first.sideEffect();
  auto& other = g.addPass("other", QueueClass::AsyncCompute);  // splits the graphics batches
  (void)other.write(y, Access::StorageWrite);
  other.sideEffect();
  auto& second = g.addPass("second", QueueClass::Graphics);
  second.read(x, Access::StorageRead);
  second.sideEffect();

  const CompiledPlan plan = compile(g, extent());
  ASSERT_EQ(plan.batches.size(), 4u);  // C, G, C, G
  EXPECT_EQ(waitsBefore(plan, "first").size(), 1u);
  EXPECT_TRUE(waitsBefore(plan, "second").empty());  // "first"'s batch already waited for value 1
  EXPECT_EQ(plan.batches[2].signalValue, 0u);
}

TEST(GraphQueues, OneWaitPerProducingQueueWithTheHighestValue) {
  RenderGraph g;
  auto a = g.createBuffer("a", BufferDesc{.size = 16});
  auto b = g.createBuffer("b", BufferDesc{.size = 16});
  auto& makeA = g.addPass("makeA", QueueClass::AsyncCompute);
  a = makeA.write(a, Access::StorageWrite);
  g.addPass("split", QueueClass::Graphics).sideEffect();
  auto& makeB = g.addPass("makeB", QueueClass::AsyncCompute);
  b = makeB.write(b, Access::StorageWrite);
  auto& use = g.addPass("use", QueueClass::Graphics);
  use.read(a, Access::Uniform, ShaderStage::Vertex);
  use.read(b, Access::StorageRead);
  use.sideEffect();

  const CompiledPlan plan = compile(g, extent());
  ASSERT_EQ(plan.batches.size(), 4u);
  EXPECT_EQ(waitsBefore(plan, "use"),
            (std::vector<SemaphoreWait>{
                {QueueClass::AsyncCompute, 2, PipelineStage::VertexShader | PipelineStage::FragmentShader}}));
  EXPECT_EQ(batchOf(plan, "makeA").signalValue, 0u);  // covered by waiting for value 2
  EXPECT_EQ(batchOf(plan, "makeB").signalValue, 2u);
}

TEST(GraphQueues, ResourcesUsedOnSeveralQueuesAreConcurrent) {
  const LuminanceGraph graph;
  const CompiledPlan plan = compile(graph.g, extent());
  EXPECT_TRUE(plan.resources[graph.hdr.id.index].desc.concurrent);
  EXPECT_TRUE(plan.resources[graph.lum.id.index].desc.concurrent);
  EXPECT_FALSE(plan.resources[graph.out.id.index].desc.concurrent);
  EXPECT_EQ(plan.resources[graph.hdr.id.index].desc.queues, QueueMask::Graphics | QueueMask::AsyncCompute);
}

TEST(GraphQueues, WriteAfterReadAcrossQueuesWaitsForTheReader) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 16});
  auto& fill = g.addPass("fill", QueueClass::Graphics, PassKind::Compute);
  auto v1 = fill.write(buf, Access::StorageWrite);
  auto& read = g.addPass("read", QueueClass::AsyncCompute);
  read.read(v1, Access::StorageRead);
  read.sideEffect();
  auto& refill = g.addPass("refill", QueueClass::Graphics, PassKind::Compute);
  g.markOutput(refill.write(v1, Access::StorageWrite));

  const CompiledPlan plan = compile(g, extent());
  EXPECT_EQ(waitsBefore(plan, "refill"),
            (std::vector<SemaphoreWait>{{QueueClass::AsyncCompute, 1, PipelineStage::ComputeShader}}));
  // Against the earlier write on its own queue it still gets a barrier (semaphore
  // chains through another queue are not relied on).
  const std::vector<Barrier> barriers = test::barriersBefore(plan, "refill", buf);
  ASSERT_EQ(barriers.size(), 1u);
  EXPECT_EQ(barriers[0].srcStages, PipelineStage::ComputeShader);
  EXPECT_EQ(barriers[0].srcAccess, AccessFlag::ShaderStorageWrite);
}

TEST(GraphQueues, AssignQueuesOnItsOwn) {
  const LuminanceGraph graph;
  const VersionTable versions = indexVersions(graph.g);
  const DependencyGraph deps = buildDependencies(graph.g, versions);
  const std::vector<PassId> order{PassId{0}, PassId{1}, PassId{2}};
  const QueueSchedule schedule = assignQueues(graph.g, order, deps);
  EXPECT_EQ(schedule.passBatch, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(schedule.waitsOf(schedule.batches[1]).size(), 1u);
  EXPECT_EQ(schedule.waitsOf(schedule.batches[2]).size(), 1u);
  EXPECT_EQ(schedule.batches[2].passes, (Range{2, 1}));
}


// More waits than assignQueues keeps room for, none covering another (each
// Transfer plus a distinct pair of other stages, at a higher value): the list
// is rewritten as one wait per stage, which must neither lose coverage nor
// invent it.
TEST(GraphQueues, ManyWaitsThatCoverNoOtherKeepTheirCoverage) {
  constexpr uint32_t kConsumers = QueueSchedule::Scratch::Waits::kStageBits + 1;
  std::vector<PipelineStage> stageSets;
  for (uint32_t a = 0; a < 8 && stageSets.size() < kConsumers; ++a)
    for (uint32_t b = a + 1; b < 8 && stageSets.size() < kConsumers; ++b)
      stageSets.push_back(PipelineStage::Transfer | static_cast<PipelineStage>((1u << a) | (1u << b)));
  ASSERT_EQ(stageSets.size(), kConsumers);
  RenderGraph g;
  DependencyGraph deps;
  const auto pair = [&](const std::string& name) {
    g.addPass("before " + name, QueueClass::AsyncCompute, PassKind::Compute);
    g.addPass(name, QueueClass::Graphics);
    return PassId{g.passCount() - 1};
  };
  for (uint32_t i = 0; i < kConsumers; ++i) {
    const PassId consumer = pair("consume" + std::to_string(i));
    deps.edges.push_back({PassId{consumer.index - 1}, consumer, ResourceId{0}, stageSets[i]});
  }
  // Every stage at the first value: covered by the waits so far.
  PipelineStage all = PipelineStage::None;
  for (const PipelineStage s : stageSets) all |= s;
  const PassId covered = pair("covered");
  deps.edges.push_back({PassId{0}, covered, ResourceId{0}, all});
  // The last value at a stage only an earlier wait had: not covered.
  ASSERT_FALSE(any(stageSets[kConsumers - 1] & PipelineStage::LateFragmentTests));
  ASSERT_TRUE(any(stageSets[kConsumers - 2] & PipelineStage::LateFragmentTests));
  const PassId uncovered = pair("uncovered");
  deps.edges.push_back({PassId{2 * kConsumers - 2}, uncovered, ResourceId{0},
                        PipelineStage::LateFragmentTests | PipelineStage::Transfer});
  std::vector<PassId> order;
  for (uint32_t p = 0; p < g.passCount(); ++p) order.push_back(PassId{p});

  const QueueSchedule schedule = assignQueues(g, order, deps);
  ASSERT_EQ(schedule.batches.size(), 2 * kConsumers + 4);
  for (uint32_t i = 0; i < kConsumers; ++i) {
    EXPECT_EQ(toVector(schedule.waitsOf(schedule.batches[2 * i + 1])),
              (std::vector<SemaphoreWait>{{QueueClass::AsyncCompute, i + 1, stageSets[i]}}))
        << "consumer " << i;
  }
  EXPECT_TRUE(schedule.waitsOf(schedule.batches[2 * kConsumers + 1]).empty());
  EXPECT_EQ(toVector(schedule.waitsOf(schedule.batches[2 * kConsumers + 3])),
            (std::vector<SemaphoreWait>{{QueueClass::AsyncCompute, kConsumers, PipelineStage::LateFragmentTests}}));
}

}  // namespace
}  // namespace sg::graph
