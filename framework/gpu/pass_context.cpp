#include <shadelgraph/gpu/pass_context.hpp>

#include <vector>

#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/gpu/pipeline.hpp>

namespace sg {

const gpu::Image& PassContext::image(graph::ResourceHandle handle) const { return executor_.image(handle.id); }

const gpu::Buffer& PassContext::buffer(graph::ResourceHandle handle) const { return executor_.buffer(handle.id); }

void PassContext::beginRendering(std::initializer_list<ColorTarget> colors, std::optional<DepthTarget> depth,
                                 bool flipY) const {
  VkExtent2D extent{0, 0};
  std::vector<VkRenderingAttachmentInfo> colorInfos;
  for (const auto& c : colors) {
    const gpu::Image& img = image(c.image);
    extent = img.extent();
    VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    a.imageView = img.view();
    a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    a.loadOp = c.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    if (c.clear) a.clearValue.color = *c.clear;
    colorInfos.push_back(a);
  }
  VkRenderingAttachmentInfo depthInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  if (depth) {
    const gpu::Image& img = image(depth->image);
    extent = img.extent();
    depthInfo.imageView = img.view();
    depthInfo.imageLayout =
        depth->readOnly ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depthInfo.loadOp = depth->clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    depthInfo.storeOp = depth->readOnly ? VK_ATTACHMENT_STORE_OP_NONE : VK_ATTACHMENT_STORE_OP_STORE;
    if (depth->clear) depthInfo.clearValue.depthStencil = {*depth->clear, 0};
  }
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, extent};
  info.layerCount = 1;
  info.colorAttachmentCount = uint32_t(colorInfos.size());
  info.pColorAttachments = colorInfos.data();
  info.pDepthAttachment = depth ? &depthInfo : nullptr;
  vkCmdBeginRendering(cmd_, &info);
  const float w = float(extent.width), h = float(extent.height);
  VkViewport viewport = flipY ? VkViewport{0, h, w, -h, 0, 1} : VkViewport{0, 0, w, h, 0, 1};
  VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd_, 0, 1, &viewport);
  vkCmdSetScissor(cmd_, 0, 1, &scissor);
  vkCmdSetCullMode(cmd_, VK_CULL_MODE_NONE);  // dynamic in every pipeline; draws may change it
  vkCmdSetFrontFace(cmd_, VK_FRONT_FACE_COUNTER_CLOCKWISE);  // likewise (mirrored instances flip it)
}

void PassContext::bind(const gpu::Pipeline& pipeline, std::initializer_list<gpu::DescriptorWrite> writes) const {
  bind(pipeline, std::span<const gpu::DescriptorWrite>(writes.begin(), writes.size()));
}

void PassContext::bind(const gpu::Pipeline& pipeline, std::span<const gpu::DescriptorWrite> writes) const {
  vkCmdBindPipeline(cmd_, pipeline.bindPoint(), pipeline.handle());
  if (!writes.empty()) descriptors_.bind(cmd_, pipeline, writes);
}

}  // namespace sg
