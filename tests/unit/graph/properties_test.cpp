// Invariants every compiled plan must hold, checked on seeded random graphs.

#include "plan_queries.hpp"

#include <shadelgraph/graph/dependencies.hpp>

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <random>

namespace sg::graph {
namespace {

using test::extent;

// Passes reading 1-3 recent results and writing 1-2 (new transients or new
// versions), a fifth on the async-compute queue, the last writing an import.
RenderGraph randomGraph(uint32_t passCount, uint32_t seed) {
  std::mt19937 rng(seed);
  const auto below = [&](uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(rng); };
  RenderGraph g;
  std::vector<ResourceHandle> latest;  // per resource written so far
  for (uint32_t p = 0; p < passCount; ++p) {
    const bool async = below(5) == 0;
    Pass& pass = g.addPass("p" + std::to_string(p), async ? QueueClass::AsyncCompute : QueueClass::Graphics,
                           PassKind::Compute);
    std::vector<uint32_t> read;
    for (uint32_t i = latest.empty() ? 0 : 1 + below(3); i > 0; --i) {
      const uint32_t r = static_cast<uint32_t>(latest.size()) - 1 - below(std::min<uint32_t>(6, latest.size()));
      if (std::find(read.begin(), read.end(), r) != read.end()) continue;
      read.push_back(r);
      const bool image = g.resource(latest[r].id).type == ResourceType::Image;
      pass.read(latest[r], image && below(2) ? Access::Sampled : Access::StorageRead);
    }
    for (uint32_t i = 1 + below(2); i > 0; --i) {
      uint32_t r = static_cast<uint32_t>(latest.size());
      if (!latest.empty() && below(4) == 0) r = static_cast<uint32_t>(latest.size()) - 1 - below(std::min<uint32_t>(6, latest.size()));
      if (std::find(read.begin(), read.end(), r) != read.end()) continue;
      if (r == latest.size()) {
        latest.push_back(below(2) ? g.createImage("r" + std::to_string(r), ImageDesc{.size = Size::relative(0.5f)})
                                  : g.createBuffer("r" + std::to_string(r), BufferDesc{.size = 1024u << below(6)}));
      }
      read.push_back(r);  // not twice in one pass
      latest[r] = pass.write(latest[r], Access::StorageWrite);
    }
  }
  auto out = g.importImage("output", ImageDesc{}, ImportedState{}, FinalState{.layout = Layout::TransferSrc});
  auto& last = g.addPass("present", QueueClass::Graphics);
  last.read(latest.back(), g.resource(latest.back().id).type == ResourceType::Image ? Access::Sampled
                                                                                     : Access::StorageRead);
  g.markOutput(last.write(out, Access::ColorAttachment));
  return g;
}

// `later` shares bytes with `earlier`: every use of `earlier` on another queue
// than `later`'s first use is in a batch that queue waited for by then, and
// `later`'s discard barrier chains with such a wait.
void checkTakeOverIsOrdered(const CompiledPlan& plan, const std::vector<uint64_t>& value, uint32_t earlier,
                            uint32_t later) {
  const PlannedPass& taker = plan.passes[plan.order[plan.resources[later].firstUse].index];
  PipelineStage waited = PipelineStage::None;
  for (uint32_t p = 0; p < plan.passes.size(); ++p) {
    const PlannedPass& pass = plan.passes[p];
    if (pass.culled || pass.queue == taker.queue) continue;
    bool uses = false;
    for (const ResourceAccess& a : plan.accessesOf(PassId{p})) uses = uses || a.resource.index == earlier;
    if (!uses) continue;
    bool covered = false;
    for (uint32_t b = 0; b <= taker.batch; ++b) {
      if (plan.batches[b].queue != taker.queue) continue;
      for (const SemaphoreWait& w : plan.waitsOf(plan.batches[b])) {
        if (w.queue != pass.queue || w.value < value[pass.batch]) continue;
        covered = true;
        waited |= w.dstStages;
      }
    }
    EXPECT_TRUE(covered) << plan.resources[later].name << " takes over " << plan.resources[earlier].name
                         << " while " << pass.name << " may still use it";
  }
  if (!any(waited)) return;
  bool chained = false;
  for (const Barrier& b : plan.barriersBefore(PassId{static_cast<uint32_t>(&taker - plan.passes.data())})) {
    chained = chained || (b.resource.index == later && b.discard && any(b.srcStages & waited));
  }
  EXPECT_TRUE(chained) << plan.resources[later].name << "'s discard barrier does not chain with the wait";
}

void checkInvariants(const RenderGraph& g, const CompiledPlan& plan) {
  const VersionTable versions = indexVersions(g);
  const DependencyGraph deps = buildDependencies(g, versions);
  // A batch's timeline value: its 1-based position among its queue's batches.
  std::vector<uint64_t> value(plan.batches.size());
  std::array<uint64_t, kQueueClassCount> count{};
  for (uint32_t b = 0; b < plan.batches.size(); ++b) value[b] = ++count[queueIndex(plan.batches[b].queue)];
  for (const Dependency& e : deps.edges) {
    const PlannedPass& from = plan.passes[e.from.index];
    const PlannedPass& to = plan.passes[e.to.index];
    if (from.culled || to.culled) continue;
    ASSERT_LT(from.orderIndex, to.orderIndex) << from.name << " -> " << to.name;
    if (from.queue == to.queue) continue;
    // Some batch on the consumer's queue, up to the consumer's, waits for the producer's batch or a later one.
    const uint64_t needed = value[from.batch];
    bool covered = false;
    for (uint32_t b = 0; b <= to.batch && !covered; ++b) {
      if (plan.batches[b].queue != to.queue) continue;
      for (const SemaphoreWait& w : plan.waitsOf(plan.batches[b])) {
        covered = covered || (w.queue == from.queue && w.value >= needed && contains(w.dstStages, e.dstStages));
      }
    }
    EXPECT_TRUE(covered) << from.name << " -> " << to.name << " crosses queues without a wait";
  }
  // Every wait names a batch that signals exactly that value.
  for (const Batch& batch : plan.batches) {
    for (const SemaphoreWait& w : plan.waitsOf(batch)) {
      bool signalled = false;
      for (uint32_t b = 0; b < plan.batches.size(); ++b) {
        const Batch& other = plan.batches[b];
        signalled = signalled || (other.queue == w.queue && value[b] == w.value && other.signalValue == w.value);
      }
      EXPECT_TRUE(signalled);
    }
  }
  // Transients sharing bytes never share lifetimes.
  for (uint32_t a = 0; a < plan.resources.size(); ++a) {
    const PlannedResource& x = plan.resources[a];
    if (!x.memory.placed()) continue;
    EXPECT_TRUE(isTransient(x.kind));
    for (uint32_t b = a + 1; b < plan.resources.size(); ++b) {
      const PlannedResource& y = plan.resources[b];
      if (!y.memory.placed() || x.memory.heap != y.memory.heap) continue;
      const bool bytes = x.memory.offset < y.memory.offset + y.memory.size && y.memory.offset < x.memory.offset + x.memory.size;
      const bool times = x.firstUse <= y.lastUse && y.firstUse <= x.lastUse;
      EXPECT_FALSE(bytes && times) << x.name << " and " << y.name << " overlap";
      if (bytes) checkTakeOverIsOrdered(plan, value, x.lastUse < y.firstUse ? a : b, x.lastUse < y.firstUse ? b : a);
    }
  }
}

TEST(GraphProperties, RandomGraphsCompileToConsistentPlans) {
  for (uint32_t seed = 1; seed <= 40; ++seed) {
    const RenderGraph g = randomGraph(10 + seed * 3, seed);
    const CompiledPlan plan = compile(g, extent(640, 360));
    SCOPED_TRACE("seed " + std::to_string(seed));
    checkInvariants(g, plan);
    if (HasFatalFailure()) return;
  }
}

// Relative sizes round down, to at least one texel; zero outputs and scales
// that are not positive give zero.
TEST(GraphProperties, RelativeSizesRoundDownToAtLeastOneTexel) {
  const auto resolved = [](float scaleX, float scaleY, uint32_t width, uint32_t height) {
    const ResolvedImageDesc d = resolveImageDesc(ImageDesc{.size = Size::relative(scaleX, scaleY)}, width, height);
    return std::array<uint32_t, 2>{d.width, d.height};
  };
  EXPECT_EQ(resolved(1.0f, 0.5f, 1920, 1080), (std::array<uint32_t, 2>{1920, 540}));
  EXPECT_EQ(resolved(0.3f, 0.75f, 5, 7), (std::array<uint32_t, 2>{1, 5}));
  EXPECT_EQ(resolved(0.001f, 0.25f, 100, 3), (std::array<uint32_t, 2>{1, 1}));
  EXPECT_EQ(resolved(0.0f, -1.0f, 100, 100), (std::array<uint32_t, 2>{0, 0}));
  EXPECT_EQ(resolved(std::numeric_limits<float>::quiet_NaN(), 2.0f, 100, 0), (std::array<uint32_t, 2>{0, 0}));
  EXPECT_EQ(resolved(std::numeric_limits<float>::infinity(), 1.0f, 0, 64), (std::array<uint32_t, 2>{0, 64}));
}

}  // namespace
}  // namespace sg::graph
