// Two frames in flight on the device, validation and synchronization
// validation on: each frame composites (graphics) what the previous frame's
// shade frame (async compute, the frame's tail) wrote into a persistent image,
// while the host does not wait for that tail before recording the next frame.
// The persistent pair is swapped every frame (current / history), so each
// image is written on async compute and read on graphics in turn, and only
// the timeline waits derived from the plan order them across frames.
#include "device_fixture.hpp"

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/gpu/readback.hpp>

namespace sg::test {
namespace {

constexpr uint32_t kSize = 32;

const char* kFullscreenVert = R"(#version 460
void main() { gl_Position = vec4(vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2) * 2.0 - 1.0, 0.0, 1.0); })";
const char* kCopyFrag = R"(#version 460
layout(set = 0, binding = 0) uniform sampler2D src;
layout(location = 0) out vec4 color;
void main() { color = texelFetch(src, ivec2(gl_FragCoord.xy), 0); })";
// A whole "shade frame": every texel gets this frame's value.
const char* kShadeComp = R"(#version 460
layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0, rgba8) uniform writeonly image2D dst;
layout(push_constant) uniform Frame { uint frame; };
void main() { imageStore(dst, ivec2(gl_GlobalInvocationID.xy), vec4(float(frame % 256u) / 255.0, 0.0, 1.0, 1.0)); })";

class FramesInFlightTest : public DeviceTest {
 protected:
  void SetUp() override {
    DeviceTest::SetUp();
    device = std::make_unique<gpu::Device>(*context, gpu::DeviceOptions{cacheDir});
    device->shaders().add("t/fullscreen.vert", kFullscreenVert);
    device->shaders().add("t/copy.frag", kCopyFrag);
    device->shaders().add("t/shade.comp", kShadeComp);
    output.emplace(*context, device->memory(),
                   gpu::ImageDesc{.width = kSize, .height = kSize, .format = VK_FORMAT_R8G8B8A8_UNORM,
                                  .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                  .name = "output"});
    for (auto& image : storage)
      image.emplace(*context, device->memory(),
                    gpu::ImageDesc{.width = kSize, .height = kSize, .format = VK_FORMAT_R8G8B8A8_UNORM,
                                   .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                   .concurrent = true, .name = "shaded"});
    clearStorage();
  }
  // Both start as frame 0's shade frame would leave them: cleared, in the resting layout.
  void clearStorage() {
    context->submitAndWait([&](VkCommandBuffer cmd) {
      for (auto& image : storage) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.dstStageMask = VK_PIPELINE_STAGE_2_CLEAR_BIT;
        b.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = image->handle();
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dep.imageMemoryBarrierCount = 1;
        dep.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dep);
        const VkClearColorValue black{};
        vkCmdClearColorImage(cmd, image->handle(), VK_IMAGE_LAYOUT_GENERAL, &black, 1, &b.subresourceRange);
      }
    });
  }
  void TearDown() override {
    for (auto& image : storage) image.reset();
    output.reset();
    device.reset();
    DeviceTest::TearDown();
  }

  // Frame `frame`: composite (graphics) copies last frame's shading to the
  // output; shade-frame (async compute, the tail) writes this frame's.
  struct Frame {
    gpu::FrameTimings timings;
    graph::CompiledPlan plan;
  };
  Frame run(gpu::GraphExecutor& executor, uint32_t frame) {
    graph::RenderGraph g;
    const graph::ResourceState resting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                       graph::AccessFlag::None};
    auto current = g.importPersistentImage(
        "shaded", {.format = graph::Format::RGBA8Unorm, .size = graph::Size::absolute(kSize, kSize)}, resting);
    auto previous = g.history(current);
    auto out = g.importImage("output", {.format = graph::Format::RGBA8Unorm, .size = graph::Size::absolute(kSize, kSize)},
                             {graph::Layout::Undefined},
                             {graph::Layout::TransferSrc, graph::PipelineStage::Transfer, graph::AccessFlag::TransferRead});
    VkSampler sampler = device->nearestSampler();
    auto& composite = g.addPass("composite", graph::QueueClass::Graphics);
    composite.read(previous, graph::Access::Sampled);
    out = composite.write(out, graph::Access::ColorAttachment);
    composite.execute([=](PassContext& ctx) {
      const auto& pipeline = ctx.device().pipeline("t/copy", [] {
        return gpu::GraphicsPipelineDesc{.vertex = {.path = "t/fullscreen.vert"}, .fragment = {.path = "t/copy.frag"},
                                         .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER}}},
                                         .colorFormats = {VK_FORMAT_R8G8B8A8_UNORM}};
      });
      ctx.beginRendering({ColorTarget{out}});
      ctx.bind(pipeline, {{0, gpu::ImageBinding{ctx.image(previous).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, sampler}}});
      vkCmdDraw(ctx.cmd(), 3, 1, 0, 0);
      ctx.endRendering();
    });
    g.markOutput(out);
    auto& shade = g.addPass("shade-frame", graph::QueueClass::AsyncCompute);
    current = shade.write(current, graph::Access::StorageWrite);
    shade.execute([=](PassContext& ctx) {
      const auto& pipeline = ctx.device().pipeline("t/shade", [] {
        return gpu::ComputePipelineDesc{
            .shader = {.path = "t/shade.comp"},
            .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}}, .pushConstantBytes = 4}};
      });
      ctx.bind(pipeline, {{0, gpu::ImageBinding{ctx.image(current).view(), VK_IMAGE_LAYOUT_GENERAL}}});
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, 4, &frame);
      vkCmdDispatch(ctx.cmd(), kSize / 8, kSize / 8, 1);
    });

    Frame f;
    f.plan = executor.compile(g, {.outputWidth = kSize, .outputHeight = kSize});
    executor.bindImage(out, *output);
    executor.bindImage(current, *storage[frame % 2]);
    executor.bindImage(previous, *storage[(frame + 1) % 2]);
    f.timings = executor.execute(g, f.plan);
    return f;
  }

  std::unique_ptr<gpu::Device> device;
  std::optional<gpu::Image> output;
  std::optional<gpu::Image> storage[2];
};

// 30 frames, two in flight: frame k shows what frame k - 1's shade frame
// wrote, the shade frame is the tail (not waited for), and every tail is
// timed once it completed.
TEST_F(FramesInFlightTest, EachFrameShowsThePreviousShadeFrame) {
  gpu::GraphExecutor executor(*device);
  executor.setFramesInFlight(2);
  ASSERT_EQ(executor.framesInFlight(), 2u);
  constexpr uint32_t kFrames = 30;
  size_t tails = 0;
  for (uint32_t frame = 0; frame < kFrames; ++frame) {
    const Frame f = run(executor, frame);
    ASSERT_EQ(f.plan.batches.size(), 2u);
    EXPECT_FALSE(f.plan.batches[0].tail);
    EXPECT_TRUE(f.plan.batches[1].tail);
    ASSERT_EQ(f.timings.passes.size(), 2u);
    EXPECT_FALSE(f.timings.passes[0].tail);
    EXPECT_TRUE(f.timings.passes[1].tail) << "frame " << frame;
    // Each queue has one batch a frame, so frame k's batches signal k + 1. The
    // composite waits for the last frame's shade frame, which wrote what it
    // reads; the shade frame for the last frame's composite, which read what
    // it overwrites. Neither wait is in the plan: they cross frames.
    using Wait = gpu::GraphExecutor::SubmittedWait;
    const auto& waits = executor.lastFrameWaits();
    ASSERT_EQ(waits.size(), 2u);
    if (frame == 0) {
      EXPECT_TRUE(waits[0].empty());
      EXPECT_TRUE(waits[1].empty());
    } else {
      EXPECT_EQ(waits[0], (std::vector<Wait>{{graph::QueueClass::AsyncCompute, frame}})) << "frame " << frame;
      EXPECT_EQ(waits[1], (std::vector<Wait>{{graph::QueueClass::Graphics, frame}})) << "frame " << frame;
    }
    const auto image = gpu::readImage(*context, device->memory(), *output, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    const uint8_t expected = frame == 0 ? 0 : uint8_t(frame - 1);
    EXPECT_EQ(image.pixel(0, 0)[0], expected) << "frame " << frame;
    EXPECT_EQ(image.pixel(kSize - 1, kSize - 1)[0], expected) << "frame " << frame;
    EXPECT_EQ(image.pixel(3, 7)[2], frame == 0 ? 0 : 255) << "frame " << frame;
    tails += executor.takeCompletedTails().size();
  }
  EXPECT_EQ(tails, kFrames - 2) << "the two slots' last tails are still in flight";
  executor.finish();
  const auto last = executor.takeCompletedTails();
  ASSERT_EQ(last.size(), 2u);
  EXPECT_EQ(last.back().frame, kFrames - 1);
  ASSERT_EQ(last.back().passes.size(), 1u);
  EXPECT_EQ(last.back().passes[0].name, "shade-frame");
  EXPECT_GE(last.back().passes[0].gpuMs, 0.0);
  EXPECT_GT(executor.commandBufferCount(), 2u) << "each slot records its own command buffers";
}

// With one frame in flight the same frames give the same images, the host
// waits for everything and no pass is left to time later.
TEST_F(FramesInFlightTest, OneFrameInFlightGivesTheSameImages) {
  std::vector<gpu::HostImage> images;
  {
    gpu::GraphExecutor one(*device);
    for (uint32_t frame = 0; frame < 6; ++frame) {
      const Frame f = run(one, frame);
      for (const auto& p : f.timings.passes) EXPECT_FALSE(p.tail);
      EXPECT_GE(f.timings.passes[1].gpuMs, 0.0);
      images.push_back(gpu::readImage(*context, device->memory(), *output, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL));
    }
    EXPECT_TRUE(one.takeCompletedTails().empty());
  }
  clearStorage();
  gpu::GraphExecutor two(*device);
  two.setFramesInFlight(2);
  for (uint32_t frame = 0; frame < 6; ++frame) {
    run(two, frame);
    const auto image = gpu::readImage(*context, device->memory(), *output, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(image.rgba8, images[frame].rgba8) << "frame " << frame;
  }
  two.finish();
}

}  // namespace
}  // namespace sg::test
