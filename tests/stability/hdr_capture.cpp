#include "hdr_capture.hpp"

#include <cstring>

#include <glm/gtc/packing.hpp>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/frame_context.hpp>
#include <shadelgraph/render/light_binding.hpp>

namespace sg::test {

void HdrCapture::registerIn(plugin::Registry& registry, const nlohmann::json& exposure,
                            const nlohmann::json& lightCull) {
  registry.beginPlugin("stability-test");
  // The capture is the only reader of the version it copies (readers on several
  // queues would share one General layout, which exposure's and tonemap's
  // descriptors do not expect): exposure and tonemap get a copy.
  registry.addPass({.name = "hdr-capture",
                    .description = "copies the HDR colour to the host",
                    .reads = {"scene.hdr"},
                    .writes = {"scene.hdr"},
                    .declare = [this](render::FrameContext& frame) {
                      auto& graph = frame.graph();
                      const auto color = frame.read("scene.hdr");
                      auto copy = graph.createImage("hdr (captured)", {.format = graph::Format::RGBA16F});
                      auto& pass = graph.addPass("hdr-capture", graph::QueueClass::Graphics, graph::PassKind::Transfer);
                      pass.read(color, graph::Access::TransferSrc);
                      copy = pass.write(copy, graph::Access::TransferDst);
                      pass.execute([this, color, copy](PassContext& ctx) { record(ctx, ctx.image(color), ctx.image(copy)); });
                      frame.write("scene.hdr", copy);
                    }});
  registry.addPass({.name = "exposure-capture",
                    .description = "copies the exposure pass's result to the host",
                    .reads = {"scene.exposure"},
                    .writes = {"scene.exposure"},
                    .declare = [this](render::FrameContext& frame) {
                      auto& graph = frame.graph();
                      const auto metered = frame.read("scene.exposure");
                      auto copy = graph.createBuffer("exposure (captured)", {.size = sizeof(shader::SgExposure)});
                      auto& pass = graph.addPass("exposure-capture", graph::QueueClass::Graphics, graph::PassKind::Transfer);
                      pass.read(metered, graph::Access::TransferSrc);
                      copy = pass.write(copy, graph::Access::TransferDst);
                      pass.execute([this, metered, copy](PassContext& ctx) {
                        if (!exposure_)
                          exposure_ = gpu::Buffer(device_->context(), device_->memory(),
                                                  {sizeof(shader::SgExposure), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                   gpu::MemoryLocation::Readback, "exposure capture", "readback"});
                        const VkBufferCopy region{0, 0, sizeof(shader::SgExposure)};
                        for (VkBuffer target : {exposure_.handle(), ctx.buffer(copy).handle()})
                          vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(metered).handle(), target, 1, &region);
                        gpu::hostReadAfterCopy(ctx.cmd());
                      });
                      frame.write("scene.exposure", copy);
                    }});
  // The decoupled frame (which shades forward objects too) with the HDR capture last before
  // exposure and the exposure capture between exposure and tonemap.
  registry.addPass({.name = "light-grid-capture",
                    .description = "copies the light grid to the host (only when the frame has one)",
                    .reads = {},
                    .writes = {render::kLightGridResource},
                    .declare = [this](render::FrameContext& frame) {
                      lightGrid_.reset();
                      if (!frame.has(render::kLightGridResource)) return;
                      auto& graph = frame.graph();
                      const auto grid = frame.read(render::kLightGridResource);
                      const uint64_t bytes = graph.resource(grid.id).buffer.size;
                      auto copy = graph.createBuffer("light grid (captured)", {.size = bytes});
                      auto& pass = graph.addPass("light-grid-capture", graph::QueueClass::Graphics,
                                                 graph::PassKind::Transfer);
                      pass.read(grid, graph::Access::TransferSrc);
                      copy = pass.write(copy, graph::Access::TransferDst);
                      lightGrid_ = std::make_shared<gpu::Buffer>(device_->context(), device_->memory(),
                                                                 gpu::BufferDesc{bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                                                 gpu::MemoryLocation::Readback,
                                                                                 "light grid capture", "readback"});
                      pass.execute([target = lightGrid_, grid, copy, bytes](PassContext& ctx) {
                        const VkBufferCopy region{0, 0, bytes};
                        for (VkBuffer to : {target->handle(), ctx.buffer(copy).handle()})
                          vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(grid).handle(), to, 1, &region);
                        gpu::hostReadAfterCopy(ctx.cmd());
                      });
                      frame.write(render::kLightGridResource, copy);
                    }});
  std::map<std::string, nlohmann::json> parameters;
  if (exposure.is_object()) parameters["exposure"] = exposure;
  if (lightCull.is_object()) parameters["light-cull"] = lightCull;
  registry.addFrame({.name = kHdrCapturedFrame,
                     .base = "decoupled",
                     // light-grid-capture first: while it holds shadel-clear back, the tie
                     // between the ready entries goes to it, not to hdr-capture.
                     .passes = {{.pass = "light-grid-capture", .after = {"light-cull"}, .before = {"shadel-clear"}},
                                {.pass = "hdr-capture", .before = {"exposure"}},
                                {.pass = "exposure-capture", .after = {"exposure"}, .before = {"tonemap"}}},
                     .parameters = parameters});
  registry.addFrame({.name = kHdrFinalCapturedFrame,
                     .base = "decoupled",
                     .passes = {{.pass = "hdr-capture", .after = {"bloom"}, .before = {"tonemap"}},
                                {.pass = "exposure-capture", .after = {"exposure"}, .before = {"tonemap"}}},
                     .parameters = parameters});
}

shader::SgExposure HdrCapture::exposure() const {
  shader::SgExposure e{};
  if (exposure_) std::memcpy(&e, exposure_.mapped(), sizeof e);
  return e;
}

void HdrCapture::record(PassContext& ctx, const gpu::Image& hdr, const gpu::Image& copy) {
  width_ = hdr.desc().width;
  height_ = hdr.desc().height;
  const VkDeviceSize bytes = VkDeviceSize(width_) * height_ * 8;  // RGBA16F
  if (!buffer_ || buffer_.size() < bytes)
    buffer_ = gpu::Buffer(device_->context(), device_->memory(),
                          {bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryLocation::Readback, "hdr capture",
                           "readback"});
  // Last frame's copy and host read are done (frames are waited for).
  gpu::memoryBarrier(ctx.cmd(), {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                     {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT});
  const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  VkBufferImageCopy region{};
  region.imageSubresource = layers;
  region.imageExtent = {width_, height_, 1};
  vkCmdCopyImageToBuffer(ctx.cmd(), hdr.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer_.handle(), 1, &region);
  VkImageCopy same{};
  same.srcSubresource = same.dstSubresource = layers;
  same.extent = {width_, height_, 1};
  vkCmdCopyImage(ctx.cmd(), hdr.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, copy.handle(),
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &same);
  gpu::hostReadAfterCopy(ctx.cmd());
}

std::vector<uint32_t> HdrCapture::lightGrid() const {
  if (!lightGrid_) return {};
  std::vector<uint32_t> out(lightGrid_->size() / sizeof(uint32_t));
  std::memcpy(out.data(), lightGrid_->mapped(), out.size() * sizeof(uint32_t));
  return out;
}

std::vector<glm::vec4> HdrCapture::pixels() const {
  std::vector<glm::vec4> out(size_t(width_) * height_);
  const auto* halves = reinterpret_cast<const uint64_t*>(buffer_.mapped());
  for (size_t i = 0; i < out.size(); ++i) out[i] = glm::unpackHalf4x16(halves[i]);
  return out;
}

}  // namespace sg::test
