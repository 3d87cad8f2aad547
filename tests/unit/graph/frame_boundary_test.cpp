// Where a frame meets the frames before and after it: which batches the host
// waits for and which run past the frame (its tail), and where external
// resources are first and last used on each queue.
#include "plan_queries.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace sg::graph {
namespace {

using test::extent;

// The decoupled frame in miniature. mark (graphics) -> reuse-fill (async:
// last frame's shading plus what is missing) -> composite (graphics, the
// output) -> shade-frame (async: reshades everything into the persistent
// storage for later frames; nothing of this frame reads it).
struct ShadeFrameGraph {
  RenderGraph g;
  ResourceHandle marks, shaded, previous, out;

  explicit ShadeFrameGraph(bool shadeFrame = true) {
    const ImageDesc storage{.format = Format::RGBA16F, .size = Size::absolute(64, 64)};
    shaded = g.importPersistentImage("shaded", storage, {Layout::General, PipelineStage::AllCommands, AccessFlag::None});
    previous = g.history(shaded);
    marks = g.createBuffer("marks", BufferDesc{.size = 256});
    out = g.importImage("output", ImageDesc{.format = Format::RGBA8Unorm, .size = Size::relative(1.0f)},
                        ImportedState{}, FinalState{Layout::TransferSrc, PipelineStage::Transfer, AccessFlag::TransferRead});
    auto& mark = g.addPass("mark", QueueClass::Graphics);
    marks = mark.write(marks, Access::StorageWrite);
    auto& fill = g.addPass("reuse-fill", QueueClass::AsyncCompute);
    fill.read(marks, Access::StorageRead);
    fill.read(previous, Access::Sampled);
    shaded = fill.write(shaded, Access::StorageWrite);
    auto& composite = g.addPass("composite", QueueClass::Graphics);
    composite.read(shaded, Access::Sampled);
    out = composite.write(out, Access::ColorAttachment);
    g.markOutput(out);
    if (shadeFrame) {
      auto& shade = g.addPass("shade-frame", QueueClass::AsyncCompute);
      shade.read(marks, Access::StorageRead);
      shaded = shade.write(shaded, Access::StorageReadWrite);
    }
  }
};

std::vector<bool> tails(const CompiledPlan& plan) {
  std::vector<bool> out;
  for (const Batch& b : plan.batches) out.push_back(b.tail);
  return out;
}

TEST(GraphFrameBoundary, ShadeFrameAfterCompositeIsTheTail) {
  const ShadeFrameGraph graph;
  const CompiledPlan plan = compile(graph.g, extent());
  ASSERT_EQ(plan.batches.size(), 4u);
  EXPECT_EQ(test::orderNames(plan), (std::vector<std::string>{"mark", "reuse-fill", "composite", "shade-frame"}));
  EXPECT_EQ(tails(plan), (std::vector<bool>{false, false, false, true}));
  EXPECT_EQ(plan.hostWaitBatch[queueIndex(QueueClass::Graphics)], 2u);
  EXPECT_EQ(plan.hostWaitBatch[queueIndex(QueueClass::AsyncCompute)], 1u) << "reuse-fill feeds composite";
  EXPECT_EQ(plan.hostWaitBatch[queueIndex(QueueClass::Transfer)], kInvalidIndex);
  // The shade frame waits for composite's read of the storage it overwrites (in the frame: a plan wait).
  const auto waits = test::toVector(plan.waitsOf(plan.batches[3]));
  ASSERT_EQ(waits.size(), 1u);
  EXPECT_EQ(waits[0].queue, QueueClass::Graphics);
  EXPECT_EQ(waits[0].value, 2u);
}

TEST(GraphFrameBoundary, JsonDumpShowsTheTail) {
  const ShadeFrameGraph graph;
  const auto doc = nlohmann::json::parse(toJson(compile(graph.g, extent())));
  ASSERT_EQ(doc.at("batches").size(), 4u);
  EXPECT_FALSE(doc["batches"][2]["tail"].get<bool>());
  EXPECT_TRUE(doc["batches"][3]["tail"].get<bool>());
}

TEST(GraphFrameBoundary, ExternalResourcesListTheirFirstAndLastBatchPerQueue) {
  const ShadeFrameGraph graph;
  const CompiledPlan plan = compile(graph.g, extent());
  const auto uses = plan.externalUses;
  auto find = [&](ResourceHandle r, QueueClass q) -> const ExternalUse* {
    for (const auto& u : uses)
      if (u.resource == r.id && u.queue == q) return &u;
    return nullptr;
  };
  const ExternalUse* shadedAsync = find(graph.shaded, QueueClass::AsyncCompute);
  ASSERT_NE(shadedAsync, nullptr);
  EXPECT_EQ(shadedAsync->firstBatch, 1u);
  EXPECT_EQ(shadedAsync->lastBatch, 3u) << "the shade frame, in the tail, is its last use";
  EXPECT_EQ(shadedAsync->firstStages, PipelineStage::ComputeShader);
  const ExternalUse* shadedGraphics = find(graph.shaded, QueueClass::Graphics);
  ASSERT_NE(shadedGraphics, nullptr);
  EXPECT_EQ(shadedGraphics->firstBatch, 2u);
  EXPECT_EQ(shadedGraphics->lastBatch, 2u);
  EXPECT_EQ(shadedGraphics->firstStages, PipelineStage::FragmentShader);
  const ExternalUse* history = find(graph.previous, QueueClass::AsyncCompute);
  ASSERT_NE(history, nullptr);
  EXPECT_EQ(history->firstBatch, 1u);
  EXPECT_EQ(find(graph.previous, QueueClass::Graphics), nullptr);
  EXPECT_NE(find(graph.out, QueueClass::Graphics), nullptr);
  EXPECT_EQ(find(graph.marks, QueueClass::Graphics), nullptr) << "transients stay inside the frame";
  EXPECT_EQ(uses.size(), 4u);
}

TEST(GraphFrameBoundary, WithoutAShadeFrameNothingRunsPastTheFrame) {
  const ShadeFrameGraph graph(/*shadeFrame*/ false);
  const CompiledPlan plan = compile(graph.g, extent());
  EXPECT_EQ(tails(plan), (std::vector<bool>{false, false, false}));
}

// Async work the output needs is waited for; a side-effect pass too (it may
// write what the host reads), and so is everything before the last such batch
// on its queue.
TEST(GraphFrameBoundary, SideEffectsAndWorkTheOutputNeedsAreNotTail) {
  RenderGraph g;
  auto lum = g.createBuffer("luminance", BufferDesc{.size = 64});
  auto out = g.importImage("output", ImageDesc{.format = Format::RGBA8Unorm, .size = Size::relative(1.0f)},
                           ImportedState{}, FinalState{Layout::TransferSrc, PipelineStage::Transfer, AccessFlag::TransferRead});
  auto& avg = g.addPass("luminance", QueueClass::AsyncCompute);
  lum = avg.write(lum, Access::StorageWrite);
  auto& tonemap = g.addPass("tonemap", QueueClass::Graphics);
  tonemap.read(lum, Access::StorageRead);
  out = tonemap.write(out, Access::ColorAttachment);
  g.markOutput(out);
  auto& debug = g.addPass("debug-dump", QueueClass::AsyncCompute);
  debug.read(lum, Access::StorageRead);
  debug.sideEffect();
  const CompiledPlan plan = compile(g, extent());
  ASSERT_EQ(plan.batches.size(), 3u);
  EXPECT_EQ(tails(plan), (std::vector<bool>{false, false, false}));
  EXPECT_EQ(plan.hostWaitBatch[queueIndex(QueueClass::AsyncCompute)], 2u);
}

// A pass only later frames need, declared between two the output needs, is
// ordered after them: the tail is submitted last (on one physical queue it
// would otherwise run before what the host waits for).
TEST(GraphFrameBoundary, TailIsOrderedAfterEverythingTheResultsNeed) {
  RenderGraph g;
  auto hdr = g.createImage("hdr", ImageDesc{.format = Format::RGBA16F, .size = Size::relative(1.0f)});
  auto visible = g.importPersistentBuffer("visible next frame", BufferDesc{.size = 64},
                                          {Layout::Undefined, PipelineStage::AllCommands, AccessFlag::None});
  auto out = g.importImage("output", ImageDesc{.format = Format::RGBA8Unorm, .size = Size::relative(1.0f)},
                           ImportedState{}, FinalState{Layout::TransferSrc, PipelineStage::Transfer, AccessFlag::TransferRead});
  auto& draw = g.addPass("draw", QueueClass::Graphics);
  hdr = draw.write(hdr, Access::ColorAttachment);
  auto& record = g.addPass("record-visibility", QueueClass::AsyncCompute);
  record.read(hdr, Access::Sampled);
  visible = record.write(visible, Access::StorageWrite);
  auto& tonemap = g.addPass("tonemap", QueueClass::Graphics);
  tonemap.read(hdr, Access::Sampled);
  out = tonemap.write(out, Access::ColorAttachment);
  g.markOutput(out);
  const CompiledPlan plan = compile(g, extent());
  EXPECT_EQ(test::orderNames(plan), (std::vector<std::string>{"draw", "tonemap", "record-visibility"}));
  EXPECT_EQ(tails(plan), (std::vector<bool>{false, true}));
}

// A frame that only feeds persistent resources is all tail: the host waits for nothing.
TEST(GraphFrameBoundary, OnlyPersistentWritesIsAllTail) {
  RenderGraph g;
  auto p = g.importPersistentBuffer("accumulated", BufferDesc{.size = 64},
                                    {Layout::Undefined, PipelineStage::AllCommands, AccessFlag::None});
  auto& a = g.addPass("accumulate", QueueClass::AsyncCompute);
  p = a.write(p, Access::StorageReadWrite);
  const CompiledPlan plan = compile(g, extent());
  ASSERT_EQ(plan.batches.size(), 1u);
  EXPECT_TRUE(plan.batches[0].tail);
  for (const uint32_t b : plan.hostWaitBatch) EXPECT_EQ(b, kInvalidIndex);
}

}  // namespace
}  // namespace sg::graph
