#include "plan_queries.hpp"

#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/order.hpp>

#include <gtest/gtest.h>

#include <string>

namespace sg::graph {
namespace {

using test::colorImage;
using test::extent;
using test::orderNames;

TEST(GraphOrder, IndependentPassesKeepDeclarationOrder) {
  RenderGraph g;
  for (const char* name : {"e", "d", "c", "b", "a"}) g.addPass(name, QueueClass::Graphics).sideEffect();
  EXPECT_EQ(orderNames(compile(g, extent())), (std::vector<std::string>{"e", "d", "c", "b", "a"}));
}

TEST(GraphOrder, ConsumerDeclaredFirstRunsAfterItsProducer) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 4});
  auto& p0 = g.addPass("p0", QueueClass::Graphics, PassKind::Compute);
  g.addPass("p1", QueueClass::Graphics).sideEffect();
  auto& p2 = g.addPass("p2", QueueClass::Graphics, PassKind::Compute);
  g.addPass("p3", QueueClass::Graphics).sideEffect();
  p0.read(p2.write(buf, Access::StorageWrite), Access::StorageRead);
  p0.sideEffect();
  // p0 waits for p2; everything else keeps its place.
  EXPECT_EQ(orderNames(compile(g, extent())), (std::vector<std::string>{"p1", "p2", "p0", "p3"}));
}

TEST(GraphOrder, DiamondDeclaredBackwards) {
  RenderGraph g;
  auto x = g.createImage("x", colorImage());
  auto y = g.createImage("y", colorImage());
  auto z = g.createImage("z", colorImage());
  auto out = g.createImage("out", colorImage());
  auto& d = g.addPass("d", QueueClass::Graphics);
  auto& c = g.addPass("c", QueueClass::Graphics);
  auto& b = g.addPass("b", QueueClass::Graphics);
  auto& a = g.addPass("a", QueueClass::Graphics);
  x = a.write(x, Access::ColorAttachment);
  b.read(x, Access::Sampled);
  y = b.write(y, Access::ColorAttachment);
  c.read(x, Access::Sampled);
  z = c.write(z, Access::ColorAttachment);
  d.read(y, Access::Sampled);
  d.read(z, Access::Sampled);
  g.markOutput(d.write(out, Access::ColorAttachment));
  // b and c are both ready after a; c was declared first.
  EXPECT_EQ(orderNames(compile(g, extent())), (std::vector<std::string>{"a", "c", "b", "d"}));
}

TEST(GraphOrder, ReaderOfAVersionRunsBeforeItIsOverwritten) {
  RenderGraph g;
  auto img = g.createImage("img", colorImage());
  auto& a = g.addPass("a", QueueClass::Graphics);
  auto& overwrite = g.addPass("overwrite", QueueClass::Graphics);
  auto& reader = g.addPass("reader", QueueClass::Graphics);
  const ResourceHandle v1 = a.write(img, Access::ColorAttachment);
  g.markOutput(overwrite.write(v1, Access::ColorAttachment));
  reader.read(v1, Access::Sampled);
  reader.sideEffect();
  EXPECT_EQ(orderNames(compile(g, extent())), (std::vector<std::string>{"a", "reader", "overwrite"}));
}

TEST(GraphOrder, SameGraphCompilesToTheSameOrder) {
  const auto build = [] {
    RenderGraph g;
    std::vector<ResourceHandle> produced;
    auto& init = g.addPass("init", QueueClass::Graphics, PassKind::Compute);
    produced.push_back(init.write(g.createBuffer("b0", BufferDesc{.size = 4}), Access::StorageWrite));
    for (std::size_t i = 1; i <= 20; ++i) {
      auto& pass = g.addPass("p" + std::to_string(i), i % 3 ? QueueClass::Graphics : QueueClass::AsyncCompute,
                             PassKind::Compute);
      pass.read(produced[i / 2], Access::StorageRead);
      auto buffer = g.createBuffer("b" + std::to_string(i), BufferDesc{.size = 4});
      produced.push_back(pass.write(buffer, Access::StorageWrite));
      pass.sideEffect();
    }
    return g;
  };
  const RenderGraph first = build();
  const RenderGraph second = build();
  EXPECT_EQ(orderNames(compile(first, extent())), orderNames(compile(second, extent())));
}

TEST(GraphOrder, LongChainOrdersEveryPass) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 4});
  std::vector<Pass*> passes;
  for (int i = 0; i < 5000; ++i) passes.push_back(&g.addPass("p" + std::to_string(i), QueueClass::AsyncCompute));
  // Wire them back to front: each pass writes over what the next-declared one wrote.
  ResourceHandle version = buf;
  for (auto it = passes.rbegin(); it != passes.rend(); ++it) version = (*it)->write(version, Access::StorageWrite);
  g.markOutput(version);

  const VersionTable versions = indexVersions(g);
  const DependencyGraph deps = buildDependencies(g, versions);
  const std::vector<PassId> order = orderPasses(deps);
  ASSERT_EQ(order.size(), 5000u);
  EXPECT_EQ(order.front(), PassId{4999});
  EXPECT_EQ(order.back(), PassId{0});
}

// Dependencies that all point forward take the shortcut (no sort); one that
// points back must still be honoured, with everything else in its place.
TEST(GraphOrder, ForwardDependenciesKeepDeclarationOrderAndOneBackwardEdgeIsHonoured) {
  DependencyGraph deps;
  deps.firstEdge = {0, 1, 2, 2, 2, 2};  // 5 passes: 0 -> 1, 1 -> 3
  deps.edges = {{PassId{0}, PassId{1}, ResourceId{0}, PipelineStage::None},
                {PassId{1}, PassId{3}, ResourceId{1}, PipelineStage::None}};
  const std::vector<bool> culled{false, false, true, false, false};
  EXPECT_EQ(orderPasses(deps, culled), (std::vector<PassId>{PassId{0}, PassId{1}, PassId{3}, PassId{4}}));

  deps.firstEdge = {0, 1, 2, 2, 2, 3};  // and 4 -> 1: pass 1 waits for the later-declared pass 4
  deps.edges.push_back({PassId{4}, PassId{1}, ResourceId{2}, PipelineStage::None});
  EXPECT_EQ(orderPasses(deps, culled), (std::vector<PassId>{PassId{0}, PassId{4}, PassId{1}, PassId{3}}));
}

}  // namespace
}  // namespace sg::graph
