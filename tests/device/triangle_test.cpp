#include "device_fixture.hpp"

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/gpu/readback.hpp>

namespace sg::test {

TEST_F(DeviceTest, DrawsTriangleOffscreen) {
  // A triangle covering the lower-left half in NDC: (-1,-1), (1,-1)... in Vulkan
  // NDC y points down, so these vertices cover the top-left corner region.
  library.add("test/tri.vert", R"(#version 460
const vec2 kPos[3] = vec2[](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0));
void main() { gl_Position = vec4(kPos[gl_VertexIndex], 0.0, 1.0); }
)");
  library.add("test/tri.frag", R"(#version 460
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0, 0.5, 0.0, 1.0); }
)");
  constexpr uint32_t kSize = 64;
  gpu::Image target(*context, *memory,
                    {.width = kSize, .height = kSize, .format = VK_FORMAT_R8G8B8A8_UNORM,
                     .usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, .name = "target"});
  gpu::Pipeline pipeline(*context, *compiler, *pipelineCache,
                         gpu::GraphicsPipelineDesc{.vertex = {.path = "test/tri.vert"},
                                                   .fragment = {.path = "test/tri.frag"},
                                                   .colorFormats = {VK_FORMAT_R8G8B8A8_UNORM}});
  context->submitAndWait([&](VkCommandBuffer cmd) {
    gpu::imageBarrier(cmd, target.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, {},
                      {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT});
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{0.0f, 0.0f, 1.0f, 1.0f}};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {kSize, kSize}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &rendering);
    VkViewport viewport{0, 0, float(kSize), float(kSize), 0, 1};
    VkRect2D scissor{{0, 0}, {kSize, kSize}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.handle());
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
  });
  auto pixels = gpu::readImage(*context, *memory, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  ASSERT_EQ(pixels.width, kSize);
  auto isOrange = [](const uint8_t* p) { return p[0] == 255 && p[1] >= 127 && p[1] <= 128 && p[2] == 0; };
  auto isBlue = [](const uint8_t* p) { return p[0] == 0 && p[1] == 0 && p[2] == 255; };
  // Inside: near the top-left corner. Outside: near the bottom-right corner.
  EXPECT_TRUE(isOrange(pixels.pixel(4, 4)));
  EXPECT_TRUE(isOrange(pixels.pixel(20, 30)));
  EXPECT_TRUE(isBlue(pixels.pixel(60, 60)));
  EXPECT_TRUE(isBlue(pixels.pixel(40, 40)));
  // The hypotenuse x + y = size splits the image: count covered pixels.
  int covered = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x) covered += isOrange(pixels.pixel(x, y));
  EXPECT_NEAR(covered, kSize * kSize / 2, kSize);
}

}  // namespace sg::test
