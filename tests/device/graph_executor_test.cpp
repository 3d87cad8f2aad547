// The render graph executed on the device: graphics -> async compute ->
// graphics with transient images and a transient buffer, validation and
// synchronization validation clean, with aliasing on and off.
#include "device_fixture.hpp"

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/gpu/readback.hpp>

namespace sg::test {
namespace {

constexpr uint32_t kSize = 64;

const char* kTriangleVert = R"(#version 460
const vec2 kPos[3] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0));
void main() { gl_Position = vec4(kPos[gl_VertexIndex], 0.0, 1.0); })";
const char* kRedFrag = R"(#version 460
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0, 0.0, 0.0, 1.0); })";
const char* kFullscreenVert = R"(#version 460
void main() { gl_Position = vec4(vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0, 0.0, 1.0); })";
const char* kScaleFrag = R"(#version 460
layout(set = 0, binding = 0) uniform sampler2D src;
layout(location = 0) out vec4 color;
void main() { color = texelFetch(src, ivec2(gl_FragCoord.xy), 0) * 0.5; })";
const char* kCountComp = R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform sampler2D src;
layout(set = 0, binding = 1) buffer Count { uint covered; };
void main() {
  if (texelFetch(src, ivec2(gl_GlobalInvocationID.xy), 0).r > 0.25) atomicAdd(covered, 1u);
})";
const char* kComposeFrag = R"(#version 460
layout(set = 0, binding = 0) uniform sampler2D src;
layout(set = 0, binding = 1) readonly buffer Count { uint covered; };
layout(location = 0) out vec4 color;
void main() {
  vec4 c = texelFetch(src, ivec2(gl_FragCoord.xy), 0);
  color = vec4(c.r, c.g, float(covered) / float(textureSize(src, 0).x * textureSize(src, 0).y), 1.0);
})";
const char* kCopyFrag = R"(#version 460
layout(set = 0, binding = 0) uniform sampler2D src;
layout(location = 0) out vec4 color;
void main() { color = texelFetch(src, ivec2(gl_FragCoord.xy), 0); })";

struct Result {
  gpu::HostImage image;
  uint64_t heapBytes = 0;
  uint64_t transientBytes = 0;
  graph::CompiledPlan plan;
};

class GraphExecutorTest : public DeviceTest {
 protected:
  void SetUp() override {
    DeviceTest::SetUp();
    device = std::make_unique<gpu::Device>(*context, gpu::DeviceOptions{cacheDir});
    auto& lib = device->shaders();
    lib.add("t/tri.vert", kTriangleVert);
    lib.add("t/red.frag", kRedFrag);
    lib.add("t/fullscreen.vert", kFullscreenVert);
    lib.add("t/scale.frag", kScaleFrag);
    lib.add("t/count.comp", kCountComp);
    lib.add("t/compose.frag", kComposeFrag);
    lib.add("t/copy.frag", kCopyFrag);
    output.emplace(*context, device->memory(),
                   gpu::ImageDesc{.width = kSize, .height = kSize, .format = VK_FORMAT_R8G8B8A8_UNORM,
                                  .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  .name = "output"});
  }
  void TearDown() override {
    output.reset();
    device.reset();
    DeviceTest::TearDown();
  }

  const gpu::Pipeline& fullscreen(PassContext& ctx, const char* frag, bool withBuffer) {
    return ctx.device().pipeline(frag, [&] {
      gpu::PipelineLayoutDesc layout{.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}}};
      if (withBuffer) layout.bindings.push_back({1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
      return gpu::GraphicsPipelineDesc{.vertex = {.path = "t/fullscreen.vert"}, .fragment = {.path = frag},
                                       .layout = layout, .colorFormats = {VK_FORMAT_R8G8B8A8_UNORM}};
    });
  }

  // P1 draw -> a; P2 a*0.5 -> b; P3 (async compute) count(b) -> covered;
  // P4 compose(b, covered) -> c; P5 copy c -> output. a is dead before the
  // async batch, which waits for it: aliasing can put covered in a's memory.
  Result run(gpu::GraphExecutor& executor, bool aliasing) {
    graph::RenderGraph g;
    const graph::ImageDesc rgba{.format = graph::Format::RGBA8Unorm};
    auto a = g.createImage("a", rgba), b = g.createImage("b", rgba), c = g.createImage("c", rgba);
    auto covered = g.createBuffer("covered", {.size = 4});
    auto out = g.importImage("output", {.format = graph::Format::RGBA8Unorm, .size = graph::Size::absolute(kSize, kSize)},
                             {graph::Layout::Undefined},
                             {graph::Layout::TransferSrc, graph::PipelineStage::Transfer, graph::AccessFlag::TransferRead});
    VkSampler sampler = device->nearestSampler();
    auto sampled = [&](PassContext& ctx, graph::ResourceHandle h) {
      return gpu::ImageBinding{ctx.image(h).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sampler};
    };

    auto& p1 = g.addPass("draw", graph::QueueClass::Graphics);
    a = p1.write(a, graph::Access::ColorAttachment);
    p1.execute([a](PassContext& ctx) {
      const auto& pipeline = ctx.device().pipeline("t/tri", [] {
        return gpu::GraphicsPipelineDesc{.vertex = {.path = "t/tri.vert"}, .fragment = {.path = "t/red.frag"},
                                         .colorFormats = {VK_FORMAT_R8G8B8A8_UNORM}};
      });
      ctx.beginRendering({ColorTarget{a, VkClearColorValue{{0.0f, 0.0f, 0.0f, 1.0f}}}});
      ctx.bind(pipeline);
      vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
      ctx.endRendering();
    });
    auto& p2 = g.addPass("scale", graph::QueueClass::Graphics);
    p2.read(a, graph::Access::Sampled);
    b = p2.write(b, graph::Access::ColorAttachment);
    p2.execute([&, a, b](PassContext& ctx) {
      ctx.beginRendering({ColorTarget{b}});
      ctx.bind(fullscreen(ctx, "t/scale.frag", false), {{0, sampled(ctx, a)}});
      vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
      ctx.endRendering();
    });
    auto& clear = g.addPass("clear-count", graph::QueueClass::AsyncCompute, graph::PassKind::Transfer);
    covered = clear.write(covered, graph::Access::TransferDst);
    clear.execute([covered](PassContext& ctx) { vkCmdFillBuffer(ctx.cmd(), ctx.buffer(covered).handle(), 0, 4, 0); });
    auto& p3 = g.addPass("count", graph::QueueClass::AsyncCompute);
    p3.read(b, graph::Access::Sampled);
    covered = p3.write(covered, graph::Access::StorageReadWrite);
    p3.execute([&, b, covered](PassContext& ctx) {
      const auto& pipeline = ctx.device().pipeline("t/count", [] {
        return gpu::ComputePipelineDesc{.shader = {.path = "t/count.comp"},
                                        .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                                                {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}}};
      });
      ctx.bind(pipeline, {{0, sampled(ctx, b)}, {1, gpu::BufferBinding{ctx.buffer(covered).handle()}}});
      vkCmdDispatch(ctx.cmd(), kSize / 8, kSize / 8, 1);
    });
    auto& p4 = g.addPass("compose", graph::QueueClass::Graphics);
    p4.read(b, graph::Access::Sampled);
    p4.read(covered, graph::Access::StorageRead);
    c = p4.write(c, graph::Access::ColorAttachment);
    p4.execute([&, b, c, covered](PassContext& ctx) {
      ctx.beginRendering({ColorTarget{c}});
      ctx.bind(fullscreen(ctx, "t/compose.frag", true),
               {{0, sampled(ctx, b)}, {1, gpu::BufferBinding{ctx.buffer(covered).handle()}}});
      vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
      ctx.endRendering();
    });
    auto& p5 = g.addPass("copy", graph::QueueClass::Graphics);
    p5.read(c, graph::Access::Sampled);
    out = p5.write(out, graph::Access::ColorAttachment);
    p5.execute([&, c, out](PassContext& ctx) {
      ctx.beginRendering({ColorTarget{out}});
      ctx.bind(fullscreen(ctx, "t/copy.frag", false), {{0, sampled(ctx, c)}});
      vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
      ctx.endRendering();
    });
    g.markOutput(out);

    Result r;
    r.plan = executor.compile(g, {.outputWidth = kSize, .outputHeight = kSize, .enableAliasing = aliasing});
    executor.bindImage(out, *output);
    executor.execute(g, r.plan);
    r.heapBytes = r.plan.heapBytes;
    r.transientBytes = executor.transientBytes();
    r.image = gpu::readImage(*context, device->memory(), *output, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    return r;
  }

  std::unique_ptr<gpu::Device> device;
  std::optional<gpu::Image> output;
};

TEST_F(GraphExecutorTest, GraphicsAsyncComputeGraphicsProducesExpectedPixels) {
  gpu::GraphExecutor executor(*device);
  const Result r = run(executor, true);
  // The async pass waits on graphics, and graphics waits on it: three batches.
  ASSERT_EQ(r.plan.batches.size(), 3u);
  EXPECT_EQ(r.plan.batches[1].queue, graph::QueueClass::AsyncCompute);
  EXPECT_EQ(r.plan.waitsOf(r.plan.batches[1]).size(), 1u);
  EXPECT_EQ(r.plan.waitsOf(r.plan.batches[2]).size(), 1u);

  uint32_t covered = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) covered += r.image.pixel(x, y)[0] > 100;
  EXPECT_NEAR(double(covered), kSize * kSize / 2.0, kSize);
  // Inside the triangle: half red; outside: black. Blue carries the count the
  // async pass made, as a fraction of the pixels.
  const uint8_t* inside = r.image.pixel(4, 4);
  const uint8_t* outside = r.image.pixel(60, 60);
  EXPECT_NEAR(inside[0], 128, 1);
  EXPECT_EQ(outside[0], 0);
  const double expectedBlue = 255.0 * covered / (kSize * kSize);
  EXPECT_NEAR(inside[2], expectedBlue, 1.5);
  EXPECT_NEAR(outside[2], expectedBlue, 1.5);
}

TEST_F(GraphExecutorTest, AliasingGivesIdenticalPixelsInLessMemory) {
  gpu::GraphExecutor aliased(*device), separate(*device);
  const Result on = run(aliased, true);
  const Result off = run(separate, false);
  EXPECT_EQ(on.image.rgba8, off.image.rgba8);
  EXPECT_LT(on.heapBytes, off.heapBytes);
  EXPECT_LT(on.transientBytes, off.transientBytes);
  // The async batch waits for the graphics batch that drew a: covered (async
  // compute) takes over a's memory across queues, its discard barrier chained
  // with that wait (validation-clean, sync-val included). b, alive from scale
  // to compose, shares with nothing.
  const auto& a = on.plan.resources[0];
  const auto& covered = on.plan.resources[3];
  EXPECT_EQ(a.memory.heap, covered.memory.heap);
  EXPECT_EQ(a.memory.offset, covered.memory.offset);
  const auto coveredAliases = on.plan.aliasesOf(graph::ResourceId{3});
  EXPECT_EQ(std::vector<graph::ResourceId>(coveredAliases.begin(), coveredAliases.end()),
            std::vector<graph::ResourceId>{graph::ResourceId{0}});
  EXPECT_TRUE(on.plan.aliasesOf(graph::ResourceId{1}).empty());
}

TEST_F(GraphExecutorTest, SecondFrameReusesTransientsAndStaysClean) {
  gpu::GraphExecutor executor(*device);
  const Result first = run(executor, true);
  const Result second = run(executor, true);  // timelines continue from the first frame's values
  EXPECT_EQ(first.image.rgba8, second.image.rgba8);
  EXPECT_EQ(first.transientBytes, second.transientBytes);
}

// Frames re-record the same command buffers: one per batch, however many frames run.
TEST_F(GraphExecutorTest, FramesReuseTheirCommandBuffers) {
  gpu::GraphExecutor executor(*device);
  const Result first = run(executor, true);
  ASSERT_EQ(executor.commandBufferCount(), first.plan.batches.size());
  for (int frame = 0; frame < 20; ++frame) run(executor, true);
  EXPECT_EQ(executor.commandBufferCount(), first.plan.batches.size());
}

}  // namespace
}  // namespace sg::test
