#include "plan_queries.hpp"

#include <shadelgraph/graph/validate.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace sg::graph {
namespace {

using test::colorImage;
using test::extent;

bool contains(const std::string& text, std::string_view part) { return text.find(part) != std::string::npos; }

// The single error validate() must report, named after `pass` and `resource`.
ValidationError onlyError(const RenderGraph& g, const CompileOptions& options = extent()) {
  const std::vector<ValidationError> errors = validate(g, options);
  if (errors.size() != 1) {
    std::string all;
    for (const ValidationError& e : errors) all += "\n  " + e.what();
    ADD_FAILURE() << "expected exactly one error, got " << errors.size() << ":" << all;
  }
  return errors.empty() ? ValidationError{} : errors.front();
}

TEST(GraphValidate, ValidGraphHasNoErrors) {
  RenderGraph g;
  auto hdr = g.createImage("hdr", ImageDesc{.format = Format::RGBA16F});
  auto out = g.importImage("output", colorImage(), ImportedState{}, FinalState{.layout = Layout::TransferSrc});
  auto& scene = g.addPass("scene", QueueClass::Graphics);
  hdr = scene.write(hdr, Access::ColorAttachment);
  auto& tonemap = g.addPass("tonemap", QueueClass::Graphics);
  tonemap.read(hdr, Access::Sampled);
  out = tonemap.write(out, Access::ColorAttachment);
  g.markOutput(out);
  EXPECT_TRUE(validate(g, extent()).empty());
}

TEST(GraphValidate, ReadOfNeverWrittenTransientNamesPassAndResource) {
  RenderGraph g;
  auto hdr = g.createImage("hdr", colorImage());
  g.addPass("tonemap", QueueClass::Graphics).read(hdr, Access::Sampled);
  const std::vector<ValidationError> errors = validate(g, extent());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].pass, "tonemap");
  EXPECT_EQ(errors[0].resource, "hdr");
  EXPECT_TRUE(contains(errors[0].message, "before any pass writes it")) << errors[0].message;
}

TEST(GraphValidate, ReadOfVersionNobodyProduces) {
  RenderGraph g;
  auto buf = g.createBuffer("counts", BufferDesc{.size = 64});
  auto& fill = g.addPass("fill", QueueClass::AsyncCompute);
  const ResourceHandle v1 = fill.write(buf, Access::StorageWrite);
  auto& use = g.addPass("use", QueueClass::AsyncCompute);
  use.read(ResourceHandle{v1.id, v1.version + 1}, Access::StorageRead);  // version 2: nobody writes it
  const std::vector<ValidationError> errors = validate(g, extent());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].pass, "use");
  EXPECT_EQ(errors[0].resource, "counts");
  EXPECT_TRUE(contains(errors[0].message, "reads version 2, which no pass writes")) << errors[0].message;
}

TEST(GraphValidate, CycleNamesThePassesOnIt) {
  RenderGraph g;
  auto x = g.createBuffer("x", BufferDesc{.size = 16});
  auto y = g.createBuffer("y", BufferDesc{.size = 16});
  auto& a = g.addPass("a", QueueClass::AsyncCompute);
  auto& b = g.addPass("b", QueueClass::AsyncCompute);
  g.addPass("unrelated", QueueClass::Graphics).sideEffect();
  const ResourceHandle y1 = a.write(y, Access::StorageWrite);
  const ResourceHandle x1 = b.write(x, Access::StorageWrite);
  a.read(x1, Access::StorageRead);
  b.read(y1, Access::StorageRead);
  const std::vector<ValidationError> errors = validate(g, extent());
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].pass, "a");
  EXPECT_TRUE(contains(errors[0].message, "cycle: 'a' -> 'b' -> 'a'")) << errors[0].message;
  EXPECT_TRUE(contains(errors[0].message, "'x'") && contains(errors[0].message, "'y'")) << errors[0].message;
}

TEST(GraphValidate, IncompatibleWritesInOnePass) {
  RenderGraph g;
  auto img = g.createImage("gbuffer", colorImage());
  auto& pass = g.addPass("mixed", QueueClass::Graphics);
  (void)pass.write(img, Access::ColorAttachment);
  (void)pass.write(img, Access::StorageWrite);
  pass.sideEffect();
  const ValidationError e = onlyError(g);
  EXPECT_EQ(e.pass, "mixed");
  EXPECT_EQ(e.resource, "gbuffer");
  EXPECT_TRUE(contains(e.message, "ColorAttachment and StorageWrite")) << e.message;
}

TEST(GraphValidate, SamplingTheImageBeingRenderedToIsIncompatible) {
  RenderGraph g;
  auto img = g.createImage("accum", colorImage());
  auto& init = g.addPass("init", QueueClass::Graphics);
  img = init.write(img, Access::ColorAttachment);
  auto& feedback = g.addPass("feedback", QueueClass::Graphics);
  feedback.read(img, Access::Sampled);
  (void)feedback.write(img, Access::ColorAttachment);
  feedback.sideEffect();
  const ValidationError e = onlyError(g);
  EXPECT_EQ(e.pass, "feedback");
  EXPECT_EQ(e.resource, "accum");
  EXPECT_TRUE(contains(e.message, "incompatible")) << e.message;
}

TEST(GraphValidate, WritingAReadOnlyImport) {
  RenderGraph g;
  auto lut = g.importImage("lut", colorImage(), ImportedState{.layout = Layout::ShaderReadOnly},
                           FinalState{.layout = Layout::ShaderReadOnly}, ImportMode::ReadOnly);
  (void)g.addPass("scribble", QueueClass::AsyncCompute).write(lut, Access::StorageWrite);
  const ValidationError e = onlyError(g);
  EXPECT_EQ(e.pass, "scribble");
  EXPECT_EQ(e.resource, "lut");
  EXPECT_TRUE(contains(e.message, "read-only import")) << e.message;
}

TEST(GraphValidate, WritingAHistoryResource) {
  RenderGraph g;
  auto shadels = g.importPersistentBuffer("shadels", BufferDesc{.size = 1024},
                                          ResourceState{.stages = PipelineStage::AllCommands});
  auto previous = g.history(shadels);
  (void)g.addPass("shade", QueueClass::AsyncCompute).write(previous, Access::StorageWrite);
  const ValidationError e = onlyError(g);
  EXPECT_EQ(e.pass, "shade");
  EXPECT_EQ(e.resource, "shadels.history");
  EXPECT_TRUE(contains(e.message, "history")) << e.message;
}

TEST(GraphValidate, BranchingWriteNamesBothPasses) {
  RenderGraph g;
  auto img = g.createImage("color", colorImage());
  auto& first = g.addPass("first", QueueClass::Graphics);
  const ResourceHandle v1 = first.write(img, Access::ColorAttachment);
  (void)g.addPass("second", QueueClass::Graphics).write(img, Access::ColorAttachment);  // old handle
  g.markOutput(v1);
  const ValidationError e = onlyError(g);
  EXPECT_EQ(e.pass, "second");
  EXPECT_EQ(e.resource, "color");
  EXPECT_TRUE(contains(e.message, "pass 'first' already wrote over")) << e.message;
}

TEST(GraphValidate, ZeroSizedTransientImage) {
  RenderGraph g;
  g.createImage("empty", ImageDesc{.size = Size::absolute(0, 16)});
  const ValidationError e = onlyError(g);
  EXPECT_EQ(e.pass, "");
  EXPECT_EQ(e.resource, "empty");
  EXPECT_TRUE(contains(e.message, "zero size")) << e.message;

  RenderGraph relative;
  relative.createImage("half", ImageDesc{.size = Size::relative(0.5f)});
  const ValidationError r = onlyError(relative, CompileOptions{});  // no output extent given
  EXPECT_EQ(r.resource, "half");
  EXPECT_TRUE(contains(r.message, "output extent is 0x0")) << r.message;
}

TEST(GraphValidate, DepthFormatAsColorAttachmentAndColorAsDepth) {
  RenderGraph g;
  auto depth = g.createImage("depth", ImageDesc{.format = Format::D32F, .size = Size::absolute(8, 8)});
  auto color = g.createImage("color", colorImage());
  auto& pass = g.addPass("draw", QueueClass::Graphics);
  (void)pass.write(depth, Access::ColorAttachment);
  (void)pass.write(color, Access::DepthAttachment);
  pass.sideEffect();
  const std::vector<ValidationError> errors = validate(g, extent());
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].resource, "depth");
  EXPECT_TRUE(contains(errors[0].message, "depth format D32F as a color attachment")) << errors[0].message;
  EXPECT_EQ(errors[1].resource, "color");
  EXPECT_TRUE(contains(errors[1].message, "as a depth attachment")) << errors[1].message;
}

TEST(GraphValidate, AccessesThePassKindCannotPerform) {
  RenderGraph g;
  auto img = g.createImage("target", colorImage());
  auto& compute = g.addPass("compute", QueueClass::AsyncCompute);
  (void)compute.write(img, Access::ColorAttachment);
  g.addPass("raster-on-compute", QueueClass::AsyncCompute, PassKind::Raster).sideEffect();
  const std::vector<ValidationError> errors = validate(g, extent());
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_EQ(errors[0].pass, "compute");
  EXPECT_TRUE(contains(errors[0].message, "ColorAttachment is not possible in a Compute pass")) << errors[0].message;
  EXPECT_EQ(errors[1].pass, "raster-on-compute");
  EXPECT_TRUE(contains(errors[1].message, "Raster pass on the AsyncCompute queue")) << errors[1].message;
}

TEST(GraphValidate, ReadDeclaredWithAWritingAccess) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 4});
  auto& fill = g.addPass("fill", QueueClass::AsyncCompute);
  buf = fill.write(buf, Access::StorageWrite);
  g.addPass("oops", QueueClass::AsyncCompute).read(buf, Access::StorageWrite);
  const ValidationError e = onlyError(g);
  EXPECT_EQ(e.pass, "oops");
  EXPECT_EQ(e.resource, "buf");
  EXPECT_TRUE(contains(e.message, "use write()")) << e.message;
}

TEST(GraphValidate, PassReadingItsOwnOutput) {
  RenderGraph g;
  auto buf = g.createBuffer("buf", BufferDesc{.size = 4});
  auto& loop = g.addPass("loop", QueueClass::AsyncCompute);
  const ResourceHandle v1 = loop.write(buf, Access::StorageWrite);
  loop.read(v1, Access::StorageRead);
  const std::vector<ValidationError> errors = validate(g, extent());
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(errors[0].pass, "loop");
  EXPECT_TRUE(contains(errors[0].message, "which it writes itself")) << errors[0].message;
}

TEST(GraphValidate, CompileThrowsGraphErrorWithEveryMessage) {
  RenderGraph g;
  auto a = g.createImage("a", colorImage());
  auto b = g.createImage("b", colorImage());
  auto& pass = g.addPass("reader", QueueClass::Graphics);
  pass.read(a, Access::Sampled);
  pass.read(b, Access::Sampled);
  pass.sideEffect();
  try {
    (void)compile(g, extent());
    FAIL() << "compile() accepted an invalid graph";
  } catch (const GraphError& error) {
    EXPECT_EQ(error.errors().size(), 2u);
    const std::string text = error.what();
    EXPECT_TRUE(contains(text, "pass 'reader', resource 'a'")) << text;
    EXPECT_TRUE(contains(text, "pass 'reader', resource 'b'")) << text;
  }
}

}  // namespace
}  // namespace sg::graph
