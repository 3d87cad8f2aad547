#include "layer_history.hpp"

#include <algorithm>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/graph_to_vulkan.hpp>

namespace sg::plugins {
namespace {

// Where persistent resources rest between frames: any shader use.
const graph::ResourceState kResting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                    graph::AccessFlag::ShaderStorageRead | graph::AccessFlag::ShaderStorageWrite |
                                        graph::AccessFlag::ShaderSampledRead};

}  // namespace

gpu::Buffer& LayerHistory::remap(gpu::Device& device, uint32_t index, uint64_t bytes) {
  if (!remaps_[index])
    remaps_[index] = gpu::Buffer(device.context(), device.memory(),
                                 {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Device,
                                  index ? "remap (last frame)" : "remap", index ? "history" : "remap",
                                  /*concurrent: graphics and async compute both use it*/ true});
  return remaps_[index];
}

PersistentLayerHandles LayerHistory::declareImagePair(graph::RenderGraph& graph, gpu::Device& device,
                                                      gpu::GraphExecutor& executor, const std::string& name,
                                                      graph::Format format, uint32_t width, uint32_t height,
                                                      uint32_t current) {
  auto& pair = images_[name];
  formatBytes_[name] = graph::bytesPerTexel(format);
  if (!pair[0] || pair[0].desc().width != width || pair[0].desc().height != height) {
    executor.finish();  // a frame in flight may still use the old pair
    for (uint32_t i = 0; i < 2; ++i)
      pair[i] = gpu::Image(device.context(), device.memory(),
                           {.width = width, .height = height, .format = gpu::toVk(format),
                            .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                            .concurrent = true,  // graphics (composite) and async compute (layers) both use it
                            .name = name + (i ? " (B)" : " (A)"), .category = "history"});
    // The graph expects them resting in General.
    device.context().submitAndWait([&](VkCommandBuffer cmd) {
      for (auto& image : pair)
        gpu::imageBarrier(cmd, image.handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, {},
                          {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT});
    });
  }
  const graph::ImageDesc desc{.format = format, .size = graph::Size::absolute(width, height)};
  PersistentLayerHandles handles;
  handles.current = graph.importPersistentImage(name, desc, kResting);
  handles.history = graph.history(handles.current);
  executor.bindImage(handles.current, pair[current]);
  executor.bindImage(handles.history, pair[1 - current]);
  return handles;
}

PersistentLayerHandles LayerHistory::declareStamps(graph::RenderGraph& graph, gpu::Device& device,
                                                   gpu::GraphExecutor& executor, uint64_t chunks, uint32_t current) {
  const uint64_t bytes = std::max<uint64_t>(chunks, 1) * sizeof(uint32_t);
  for (uint32_t i = 0; i < 2; ++i)
    if (!stamps_[i] || stamps_[i].size() != bytes)
      stamps_[i] = gpu::Buffer(device.context(), device.memory(),
                               {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Device,
                                i ? "shade stamps (B)" : "shade stamps (A)", "history", /*concurrent*/ true});
  PersistentLayerHandles handles;
  handles.current = graph.importPersistentBuffer("shade stamps", {.size = bytes}, kResting);
  handles.history = graph.history(handles.current);
  executor.bindBuffer(handles.current, stamps_[current]);
  executor.bindBuffer(handles.history, stamps_[1 - current]);
  return handles;
}

LayerHistory::Declared LayerHistory::declare(graph::RenderGraph& graph, gpu::Device& device,
                                             gpu::GraphExecutor& executor, const plugin::Registry& registry,
                                             const std::vector<std::string>& layers, bool keepShading,
                                             uint32_t width, uint32_t height, uint64_t remapBytes, uint64_t frame,
                                             const std::string& outputKey) {
  Declared out;
  // Without persistent layers or reuse one remap serves every frame; with
  // them the two swap, so last frame's stays readable.
  const bool keep = keepShading || !layers.empty();
  const uint32_t current = keep ? uint32_t(frame % 2) : 0u;
  out.remap = graph.importPersistentBuffer("remap", {.size = remapBytes}, kResting);
  executor.bindBuffer(out.remap, remap(device, current, remapBytes));
  const bool consecutive = frame == lastFrame_ + 1;
  lastFrame_ = frame;
  if (!keep) {
    lastKey_.clear();
    return out;
  }
  out.previousRemap = graph.history(out.remap);
  executor.bindBuffer(out.previousRemap, remap(device, 1 - current, remapBytes));

  std::string key = outputKey + " " + std::to_string(width) + "x" + std::to_string(height) + (keepShading ? " reuse" : "");
  for (const auto& name : layers) {
    const auto& layer = registry.layer(name);
    key += " " + name;
    out.layers[name] = declareImagePair(graph, device, executor, "layer " + name, layer.format, width, height, current);
  }
  if (keepShading) {
    out.shaded = declareImagePair(graph, device, executor, "shade storage", graph::Format::RGBA16F, width, height, current);
    // The storage is width x height texels of 8x8-texel chunks; the key holds its size.
    out.stamps = declareStamps(graph, device, executor, uint64_t(width / 8) * (height / 8), current);
  }
  // Last frame must have stored these layers at this size, with this remap pair.
  out.valid = consecutive && key == lastKey_;
  lastKey_ = key;
  return out;
}

uint64_t LayerHistory::bytes() const {
  uint64_t total = remaps_[1] ? remaps_[1].size() : 0;
  for (const auto& stamps : stamps_) total += stamps ? stamps.size() : 0;
  for (const auto& [name, pair] : images_)
    for (const auto& image : pair)
      if (image) total += uint64_t(image.desc().width) * image.desc().height * formatBytes_.at(name);
  return total;
}

}  // namespace sg::plugins
