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

gpu::Buffer& LayerHistory::remap(gpu::Device& device, uint64_t bytes) {
  if (!remap_)
    remap_ = gpu::Buffer(device.context(), device.memory(),
                         {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                          gpu::MemoryLocation::Device, "remap", "remap",
                          /*concurrent: graphics and async compute both use it*/ true});
  return remap_;
}

// Images the graph expects resting in General.
void toGeneral(gpu::Device& device, std::initializer_list<gpu::Image*> images) {
  device.context().submitAndWait([&](VkCommandBuffer cmd) {
    for (auto* image : images)
      gpu::imageBarrier(cmd, image->handle(), VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, {},
                        {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT});
  });
}

gpu::Image makeStorageImage(gpu::Device& device, const std::string& name, graph::Format format, uint32_t width,
                            uint32_t height, const char* category) {
  return gpu::Image(device.context(), device.memory(),
                    {.width = width, .height = height, .format = gpu::toVk(format),
                     .usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                     .concurrent = true,  // graphics (composite) and async compute (layers) both use it
                     .name = name, .category = category});
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
      pair[i] = makeStorageImage(device, name + (i ? " (B)" : " (A)"), format, width, height, "history");
    toGeneral(device, {&pair[0], &pair[1]});
  }
  const graph::ImageDesc desc{.format = format, .size = graph::Size::absolute(width, height)};
  PersistentLayerHandles handles;
  handles.current = graph.importPersistentImage(name, desc, kResting);
  handles.history = graph.history(handles.current);
  executor.bindImage(handles.current, pair[current]);
  executor.bindImage(handles.history, pair[1 - current]);
  return handles;
}

graph::ResourceHandle LayerHistory::declareStorage(graph::RenderGraph& graph, gpu::Device& device,
                                                   gpu::GraphExecutor& executor, uint32_t width, uint32_t height) {
  if (!storage_ || storage_.desc().width != width || storage_.desc().height != height) {
    executor.finish();  // a frame in flight may still use the old image
    storage_ = makeStorageImage(device, "shade storage (kept)", graph::Format::RGBA16F, width, height, "shade storage");
    toGeneral(device, {&storage_});
  }
  const graph::ImageDesc desc{.format = graph::Format::RGBA16F, .size = graph::Size::absolute(width, height)};
  const graph::ResourceHandle handle = graph.importPersistentImage("shade storage", desc, kResting);
  executor.bindImage(handle, storage_);
  return handle;
}

graph::ResourceHandle LayerHistory::declareStamps(graph::RenderGraph& graph, gpu::Device& device,
                                                  gpu::GraphExecutor& executor, uint64_t chunks) {
  const uint64_t bytes = std::max<uint64_t>(chunks, 1) * sizeof(uint32_t);
  if (!stamps_ || stamps_.size() != bytes) {
    executor.finish();
    stamps_ = gpu::Buffer(device.context(), device.memory(),
                          {bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Device, "shade stamps",
                           "history", /*concurrent*/ true});
  }
  const graph::ResourceHandle handle = graph.importPersistentBuffer("shade stamps", {.size = bytes}, kResting);
  executor.bindBuffer(handle, stamps_);
  return handle;
}

LayerHistory::Declared LayerHistory::declare(graph::RenderGraph& graph, gpu::Device& device,
                                             gpu::GraphExecutor& executor, const plugin::Registry& registry,
                                             const std::vector<std::string>& layers, bool keepShading,
                                             uint32_t width, uint32_t height, uint64_t remapBytes, uint64_t frame,
                                             const std::string& outputKey) {
  Declared out;
  // One remap table serves every frame: where a chunk was stored last frame
  // is where it is stored now (stable allocation).
  const bool keep = keepShading || !layers.empty();
  const uint32_t current = uint32_t(frame % 2);
  out.remap = graph.importPersistentBuffer("remap", {.size = remapBytes}, kResting);
  executor.bindBuffer(out.remap, remap(device, remapBytes));
  const bool consecutive = frame == lastFrame_ + 1;
  lastFrame_ = frame;
  if (!keep) {
    lastKey_.clear();
    return out;
  }

  std::string key = outputKey + " " + std::to_string(width) + "x" + std::to_string(height) + (keepShading ? " reuse" : "");
  for (const auto& name : layers) {
    const auto& layer = registry.layer(name);
    key += " " + name;
    out.layers[name] = declareImagePair(graph, device, executor, "layer " + name, layer.format, width, height, current);
  }
  if (keepShading) {
    out.shaded = declareStorage(graph, device, executor, width, height);
    // At least one stamp per physical chunk (9x9-texel tiles); the key holds the size.
    out.stamps = declareStamps(graph, device, executor, uint64_t(width / 8) * (height / 8));
  }
  // Last frame must have stored these layers at this size, with this remap pair.
  out.valid = consecutive && key == lastKey_;
  lastKey_ = key;
  return out;
}

uint64_t LayerHistory::bytes() const {
  uint64_t total = stamps_ ? stamps_.size() : 0;
  for (const auto& [name, pair] : images_)
    for (const auto& image : pair)
      if (image) total += uint64_t(image.desc().width) * image.desc().height * formatBytes_.at(name);
  return total;
}

}  // namespace sg::plugins
