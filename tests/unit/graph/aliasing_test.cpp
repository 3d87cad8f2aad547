#include "plan_queries.hpp"

#include <shadelgraph/graph/place_transients.hpp>
#include <shadelgraph/graph/transient_peak.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace sg::graph {
namespace {

using test::aliasesOf;
using test::barriersBefore;
using test::extent;

// p1 writes a; p2 reads a, writes b; p3 reads b, writes c; p4 reads c.
// Lifetimes: a [0,1], b [1,2], c [2,3]: a and c are disjoint, b overlaps both.
struct Chain {
  RenderGraph g;
  ResourceHandle a, b, c;

  Chain() {
    a = g.createBuffer("a", BufferDesc{.size = 1000});
    b = g.createBuffer("b", BufferDesc{.size = 1000});
    c = g.createBuffer("c", BufferDesc{.size = 1000});
    auto& p1 = g.addPass("p1", QueueClass::Graphics, PassKind::Compute);
    a = p1.write(a, Access::StorageWrite);
    auto& p2 = g.addPass("p2", QueueClass::Graphics, PassKind::Compute);
    p2.read(a, Access::StorageRead);
    b = p2.write(b, Access::StorageWrite);
    auto& p3 = g.addPass("p3", QueueClass::Graphics, PassKind::Compute);
    p3.read(b, Access::StorageRead);
    c = p3.write(c, Access::StorageWrite);
    auto& p4 = g.addPass("p4", QueueClass::Graphics, PassKind::Compute);
    p4.read(c, Access::StorageRead);
    p4.sideEffect();
  }

  CompileOptions options(std::vector<MemoryRequirements> requirements, bool aliasing = true) const {
    CompileOptions o = extent();
    o.memoryRequirements = std::move(requirements);
    o.enableAliasing = aliasing;
    return o;
  }
};

const MemoryRequirements kPlain{.size = 1000, .alignment = 256, .memoryTypeBits = 0b1};

TEST(GraphAliasing, DisjointLifetimesShareMemory) {
  const Chain chain;
  const CompiledPlan plan = compile(chain.g, chain.options({kPlain, kPlain, kPlain}));
  const MemoryPlacement& a = plan.resources[chain.a.id.index].memory;
  const MemoryPlacement& c = plan.resources[chain.c.id.index].memory;
  EXPECT_EQ(a.heap, c.heap);
  EXPECT_EQ(a.offset, c.offset);
  EXPECT_EQ(aliasesOf(plan, chain.c), std::vector<ResourceId>{chain.a.id});
  EXPECT_EQ(plan.heapBytes, 2024u);  // a and c at 0, b at 1024 (aligned)
  EXPECT_EQ(plan.heapBytesWithoutAliasing, 1024u + 1024u + 1000u);
}

// The most bytes in use at once: a and b at p2 (b and c at p3 tie, the first
// is reported); no packing gets the aliased heap below it.
TEST(GraphAliasing, TransientPeakIsTheMostBytesInUseAtOnce) {
  const Chain chain;
  const CompiledPlan plan = compile(chain.g, chain.options({kPlain, kPlain, kPlain}));
  const TransientPeak peak = transientPeak(plan);
  EXPECT_EQ(peak.position, 1u);
  EXPECT_EQ(peak.pass, "p2");
  EXPECT_EQ(peak.bytes, 2000u);
  ASSERT_EQ(peak.live.size(), 2u);
  EXPECT_EQ(peak.live[0].name, "a");
  EXPECT_EQ(peak.live[1].name, "b");
  EXPECT_GE(plan.heapBytes, peak.bytes);
  // Without aliasing the peak is the same: it depends on lifetimes, not on placement.
  EXPECT_EQ(transientPeak(compile(chain.g, chain.options({kPlain, kPlain, kPlain}, false))).bytes, 2000u);
}

TEST(GraphAliasing, TransientPeakOfAPlanWithoutTransients) {
  RenderGraph g;
  auto& p = g.addPass("p", QueueClass::Graphics, PassKind::Compute);
  p.sideEffect();
  const TransientPeak peak = transientPeak(compile(g, extent()));
  EXPECT_EQ(peak.position, kInvalidIndex);
  EXPECT_EQ(peak.bytes, 0u);
  EXPECT_TRUE(peak.live.empty());
}

TEST(GraphAliasing, OverlappingLifetimesDoNotShare) {
  const Chain chain;
  const CompiledPlan plan = compile(chain.g, chain.options({kPlain, kPlain, kPlain}));
  const MemoryPlacement& b = plan.resources[chain.b.id.index].memory;
  for (const ResourceHandle other : {chain.a, chain.c}) {
    const MemoryPlacement& o = plan.resources[other.id.index].memory;
    const bool disjoint = b.offset >= o.offset + o.size || o.offset >= b.offset + b.size;
    EXPECT_TRUE(b.heap != o.heap || disjoint) << plan.resources[other.id.index].name;
  }
  EXPECT_TRUE(aliasesOf(plan, chain.b).empty());
}

TEST(GraphAliasing, AlignmentIsHonoured) {
  const Chain chain;
  const MemoryRequirements aligned{.size = 100, .alignment = 4096, .memoryTypeBits = 0b1};
  const CompiledPlan plan = compile(chain.g, chain.options({kPlain, aligned, kPlain}));
  const MemoryPlacement& b = plan.resources[chain.b.id.index].memory;
  EXPECT_EQ(b.offset % 4096, 0u);
  EXPECT_GE(b.offset, 1000u);  // after a, which it overlaps in time
  EXPECT_EQ(plan.heaps[b.heap].alignment, 4096u);
}

TEST(GraphAliasing, IncompatibleMemoryTypesDoNotShare) {
  const Chain chain;
  const MemoryRequirements typeA{.size = 1000, .alignment = 256, .memoryTypeBits = 0b01};
  const MemoryRequirements typeC{.size = 1000, .alignment = 256, .memoryTypeBits = 0b10};
  const CompiledPlan plan = compile(chain.g, chain.options({typeA, typeA, typeC}));
  const MemoryPlacement& a = plan.resources[chain.a.id.index].memory;
  const MemoryPlacement& c = plan.resources[chain.c.id.index].memory;
  EXPECT_NE(a.heap, c.heap);
  EXPECT_EQ(plan.heaps[c.heap].memoryTypeBits, 0b10u);
  EXPECT_TRUE(aliasesOf(plan, chain.c).empty());
}

TEST(GraphAliasing, OffGivesEveryTransientItsOwnRange) {
  const Chain chain;
  const CompiledPlan plan = compile(chain.g, chain.options({kPlain, kPlain, kPlain}, false));
  std::vector<MemoryPlacement> placements;
  for (const ResourceHandle r : {chain.a, chain.b, chain.c}) placements.push_back(plan.resources[r.id.index].memory);
  std::sort(placements.begin(), placements.end(),
            [](const MemoryPlacement& x, const MemoryPlacement& y) { return x.offset < y.offset; });
  for (std::size_t i = 1; i < placements.size(); ++i) {
    EXPECT_GE(placements[i].offset, placements[i - 1].offset + placements[i - 1].size);
  }
  EXPECT_EQ(plan.heapBytes, plan.heapBytesWithoutAliasing);
  EXPECT_TRUE(aliasesOf(plan, chain.c).empty());
}

TEST(GraphAliasing, TakingOverMemoryWaitsForThePreviousOccupant) {
  const Chain chain;
  const CompiledPlan plan = compile(chain.g, chain.options({kPlain, kPlain, kPlain}));
  // c reuses a's memory: its first (otherwise unneeded) buffer barrier discards
  // and waits for every access of a.
  const Barrier expected{.resource = chain.c.id,
                         .srcStages = PipelineStage::ComputeShader,
                         .dstStages = PipelineStage::ComputeShader,
                         .srcAccess = AccessFlag::ShaderStorageWrite,
                         .dstAccess = AccessFlag::ShaderStorageWrite,
                         .discard = true};
  EXPECT_EQ(barriersBefore(plan, "p3", chain.c), std::vector<Barrier>{expected});
  EXPECT_TRUE(barriersBefore(plan, "p2", chain.b).empty());  // b took over nobody's memory
}

TEST(GraphAliasing, HistoryPersistentAndImportsAreNeverPlaced) {
  RenderGraph g;
  auto layer = g.importPersistentImage("layer", ImageDesc{.size = Size::absolute(32, 32)},
                                       ResourceState{Layout::General, PipelineStage::AllCommands, AccessFlag::None});
  auto previous = g.history(layer);
  auto scratch = g.createImage("scratch", ImageDesc{.size = Size::absolute(32, 32)});
  auto& shade = g.addPass("shade", QueueClass::AsyncCompute);
  shade.read(previous, Access::StorageRead);
  scratch = shade.write(scratch, Access::StorageWrite);
  auto& resolve = g.addPass("resolve", QueueClass::AsyncCompute);
  resolve.read(scratch, Access::StorageRead);
  (void)resolve.write(layer, Access::StorageWrite);
  auto late = g.createImage("late", ImageDesc{.size = Size::absolute(32, 32)});
  auto& tail = g.addPass("tail", QueueClass::AsyncCompute);
  tail.read(previous, Access::StorageRead);
  (void)tail.write(late, Access::StorageWrite);
  tail.sideEffect();

  const CompiledPlan plan = compile(g, extent());
  for (const ResourceHandle external : {layer, previous}) {
    const PlannedResource& r = plan.resources[external.id.index];
    EXPECT_FALSE(r.memory.placed()) << r.name;
    EXPECT_TRUE(aliasesOf(plan, external).empty()) << r.name;
  }
  EXPECT_EQ(plan.resources[previous.id.index].kind, ResourceKind::History);
  EXPECT_EQ(plan.resources[previous.id.index].historyOf, layer.id);
  // The transients do alias each other (scratch is dead when late is born), never the history.
  EXPECT_EQ(aliasesOf(plan, late), std::vector<ResourceId>{scratch.id});
}

// "early" lives on async compute only; "consume" on graphics reads its
// neighbour "x", so the graphics batch waits for the async batch before
// "next" writes "late": late may take early's memory.
TEST(GraphAliasing, TransientsOnTwoQueuesOrderedByAWaitShareMemory) {
  RenderGraph g;
  auto early = g.createBuffer("early", BufferDesc{.size = 1000});
  auto x = g.createBuffer("x", BufferDesc{.size = 64});
  auto late = g.createBuffer("late", BufferDesc{.size = 1000});
  auto& fill = g.addPass("fill", QueueClass::AsyncCompute);
  early = fill.write(early, Access::StorageWrite);
  x = fill.write(x, Access::StorageWrite);
  auto& use = g.addPass("use", QueueClass::AsyncCompute);
  use.read(early, Access::StorageRead);
  use.sideEffect();
  g.addPass("consume", QueueClass::Graphics).sideEffect().read(x, Access::StorageRead);
  auto& next = g.addPass("next", QueueClass::Graphics, PassKind::Compute);
  (void)next.write(late, Access::StorageWrite);
  next.sideEffect();

  const CompiledPlan plan = compile(g, extent());
  const MemoryPlacement& e = plan.resources[early.id.index].memory;
  const MemoryPlacement& l = plan.resources[late.id.index].memory;
  EXPECT_EQ(e.heap, l.heap);
  EXPECT_EQ(e.offset, l.offset);
  EXPECT_EQ(aliasesOf(plan, late), std::vector<ResourceId>{early.id});
  // The discard barrier chains with the wait that orders the async work first.
  const std::vector<SemaphoreWait> waits = test::waitsBefore(plan, "next");
  ASSERT_EQ(waits.size(), 1u);
  EXPECT_EQ(waits[0].queue, QueueClass::AsyncCompute);
  const std::vector<Barrier> discard = barriersBefore(plan, "next", late);
  ASSERT_EQ(discard.size(), 1u);
  EXPECT_TRUE(discard[0].discard);
  EXPECT_TRUE(contains(discard[0].srcStages, waits[0].dstStages));
}

// Nothing on graphics waits for the async pass: "late" could run while
// "early" is still in use, however the order lists them.
TEST(GraphAliasing, TransientsOnTwoQueuesThatMayRunConcurrentlyDoNotShare) {
  RenderGraph g;
  auto early = g.createBuffer("early", BufferDesc{.size = 1000});
  auto late = g.createBuffer("late", BufferDesc{.size = 1000});
  auto& fill = g.addPass("fill", QueueClass::AsyncCompute);
  (void)fill.write(early, Access::StorageWrite);
  fill.sideEffect();
  auto& next = g.addPass("next", QueueClass::Graphics, PassKind::Compute);
  (void)next.write(late, Access::StorageWrite);
  next.sideEffect();

  const CompiledPlan plan = compile(g, extent());
  ASSERT_LT(plan.resources[early.id.index].lastUse, plan.resources[late.id.index].firstUse);
  EXPECT_TRUE(test::waitsBefore(plan, "next").empty());
  const MemoryPlacement& e = plan.resources[early.id.index].memory;
  const MemoryPlacement& l = plan.resources[late.id.index].memory;
  EXPECT_TRUE(e.heap != l.heap || e.offset + e.size <= l.offset || l.offset + l.size <= e.offset);
  EXPECT_TRUE(aliasesOf(plan, late).empty());
}

// A transient used on both queues gives its memory to a later graphics
// transient only once graphics waited for its async use.
TEST(GraphAliasing, ATransientUsedOnTwoQueuesIsReusedOnlyAfterTheWait) {
  RenderGraph g;
  auto shared = g.createBuffer("shared", BufferDesc{.size = 1000});
  auto tmp = g.createBuffer("tmp", BufferDesc{.size = 1000});
  auto later = g.createBuffer("later", BufferDesc{.size = 1000});
  auto& produce = g.addPass("produce", QueueClass::Graphics, PassKind::Compute);
  shared = produce.write(shared, Access::StorageWrite);
  auto& async = g.addPass("async", QueueClass::AsyncCompute);
  async.read(shared, Access::StorageRead);
  tmp = async.write(tmp, Access::StorageWrite);
  auto& after = g.addPass("after", QueueClass::Graphics, PassKind::Compute);
  after.read(tmp, Access::StorageRead);
  (void)after.write(later, Access::StorageWrite);
  after.sideEffect();

  const CompiledPlan plan = compile(g, extent());
  EXPECT_TRUE(plan.resources[shared.id.index].desc.concurrent);
  EXPECT_EQ(plan.resources[later.id.index].memory.offset, plan.resources[shared.id.index].memory.offset);
  EXPECT_EQ(aliasesOf(plan, later), std::vector<ResourceId>{shared.id});
}

TEST(GraphAliasing, PlaceTransientsOnHandMadeLifetimes) {
  // Three same-queue transients: x [0,2], y [3,5], z [1,4]. x and y may share.
  // The sweep places x, then z (aligned above x), then y where x was.
  std::vector<PlannedResource> resources(3);
  const uint32_t lifetimes[3][2] = {{0, 2}, {3, 5}, {1, 4}};
  for (uint32_t r = 0; r < 3; ++r) {
    resources[r].kind = ResourceKind::TransientBuffer;
    resources[r].desc.type = ResourceType::Buffer;
    resources[r].desc.queues = QueueMask::Graphics;
    resources[r].firstUse = lifetimes[r][0];
    resources[r].lastUse = lifetimes[r][1];
  }
  const std::vector<MemoryRequirements> requirements{
      {.size = 512, .alignment = 512, .memoryTypeBits = 1},
      {.size = 256, .alignment = 256, .memoryTypeBits = 1},
      {.size = 1024, .alignment = 1024, .memoryTypeBits = 1},
  };
  const MemoryPlan plan = placeTransients(resources, requirements, true);
  ASSERT_EQ(plan.heaps.size(), 1u);
  EXPECT_EQ(plan.placements[0].offset, 0u);
  EXPECT_EQ(plan.placements[2].offset, 1024u);  // overlaps x in time; 1024-aligned
  EXPECT_EQ(plan.placements[1].offset, 0u);     // x's range, free again (best fit)
  EXPECT_EQ(plan.heapBytes, 2048u);
  EXPECT_EQ(plan.heapBytesWithoutAliasing, 512u + 1024u + 256u + 512u);  // with x-to-z alignment padding
  EXPECT_EQ(test::toVector(plan.aliasesOf(ResourceId{1})), std::vector<ResourceId>{ResourceId{0}});
  EXPECT_TRUE(plan.aliasesOf(ResourceId{2}).empty());
}

TEST(GraphAliasing, PlacingLifetimesMatchesPlacingPlannedResources) {
  // PlanCompiler hands placement the used transients' lifetimes directly; the
  // same transients given as planned resources (with an unused one and an
  // external one in between, which are skipped) place identically, and a
  // reused MemoryPlan gives what a fresh one gives.
  std::vector<PlannedResource> resources(5);
  const uint32_t lifetimes[5][2] = {{0, 2}, {0, 0}, {3, 5}, {1, 4}, {2, 3}};
  for (uint32_t r = 0; r < 5; ++r) {
    resources[r].kind = ResourceKind::TransientBuffer;
    resources[r].desc.type = ResourceType::Buffer;
    resources[r].desc.queues = QueueMask::Graphics;
    resources[r].firstUse = lifetimes[r][0];
    resources[r].lastUse = lifetimes[r][1];
  }
  resources[1].culled = true;
  resources[4].kind = ResourceKind::Imported;
  const std::vector<MemoryRequirements> requirements{
      {.size = 512, .alignment = 512, .memoryTypeBits = 1},
      {.size = 64, .alignment = 64, .memoryTypeBits = 1},
      {.size = 256, .alignment = 256, .memoryTypeBits = 1},
      {.size = 1024, .alignment = 1024, .memoryTypeBits = 1},
      {.size = 64, .alignment = 64, .memoryTypeBits = 1},
  };
  const MemoryPlan fromResources = placeTransients(resources, requirements, true);
  const std::vector<TransientLifetime> transients{
      {2, 3, 5, QueueMask::Graphics}, {0, 0, 2, QueueMask::Graphics}, {3, 1, 4, QueueMask::Graphics}};
  MemoryPlan reused = placeTransients(resources, requirements, false);  // leaves other contents behind
  placeTransients(transients, 5, requirements, true, reused);
  EXPECT_EQ(reused.placements, fromResources.placements);
  EXPECT_EQ(reused.aliasesWith, fromResources.aliasesWith);
  EXPECT_EQ(reused.aliases, fromResources.aliases);
  EXPECT_EQ(reused.heapBytes, fromResources.heapBytes);
  EXPECT_EQ(reused.heapBytesWithoutAliasing, fromResources.heapBytesWithoutAliasing);
  EXPECT_FALSE(reused.placements[1].placed());
  EXPECT_FALSE(reused.placements[4].placed());
}

}  // namespace
}  // namespace sg::graph
