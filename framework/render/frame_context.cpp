#include <shadelgraph/render/frame_context.hpp>

#include <algorithm>
#include <iterator>

namespace sg::render {

FrameContext::FrameContext(graph::RenderGraph& graph, const FrameInputs& inputs, const SceneView& allDraws,
                           std::map<std::string, std::shared_ptr<void>>& states, const plugin::ResolvedFrame* frame)
    : graph_(graph), inputs_(inputs), all_(allDraws), states_(states), frame_(frame) {}

std::span<const plugin::ResolvedPass> FrameContext::passesBetween(const std::string& until) const {
  if (!frame_ || !pass_) return {};
  const auto& passes = frame_->passes;
  auto begin = std::find_if(passes.begin(), passes.end(), [&](const plugin::ResolvedPass& p) { return &p == pass_; });
  if (begin == passes.end()) return {};
  ++begin;
  const auto end = std::find_if(begin, passes.end(), [&](const plugin::ResolvedPass& p) { return p.pass->name == until; });
  return {begin, end};
}

bool FrameContext::runsLater(const std::string& pass) const {
  if (!frame_ || !pass_) return false;
  const auto later = passesBetween(pass);
  return later.data() + later.size() != frame_->passes.data() + frame_->passes.size();
}

SceneView FrameContext::view(std::span<const uint32_t> draws) const {
  return {all_.scene,     all_.frameUniforms, all_.lights, all_.noLightGrid, draws, all_.materials,
          all_.layerTextures, resources_,       &drawCommands_, VK_NULL_HANDLE, all_.backFacesHidden};
}

std::span<const uint32_t> FrameContext::visibleDraws() {
  visible_.clear();
  visible_.insert(visible_.end(), draws_.forward.begin(), draws_.forward.end());
  visible_.insert(visible_.end(), draws_.decoupled.begin(), draws_.decoupled.end());
  std::sort(visible_.begin(), visible_.end());
  return visible_;
}

graph::ResourceHandle FrameContext::read(const std::string& resource) const {
  auto it = resources_.find(resource);
  if (it == resources_.end())
    throw plugin::FrameError("pass '" + passName() + "' reads frame resource '" + resource +
                             "', which no earlier pass of this frame wrote");
  return it->second;
}

void FrameContext::write(const std::string& resource, graph::ResourceHandle handle) {
  if (pass_) {
    const auto& writes = pass_->pass->writes;
    if (std::find(writes.begin(), writes.end(), resource) == writes.end())
      throw plugin::FrameError("pass '" + passName() + "' writes frame resource '" + resource +
                               "', which its registration does not declare");
  }
  resources_[resource] = handle;
}

const std::string& FrameContext::passName() const {
  static const std::string renderer = "renderer";
  return pass_ ? pass_->pass->name : renderer;
}

const nlohmann::json& FrameContext::parameters() const {
  static const nlohmann::json none = nlohmann::json::object();
  return pass_ ? pass_->parameters : none;
}

void* FrameContext::stateOrThrow(const std::string& key) const {
  auto it = states_.find(key);
  if (it == states_.end() || !it->second)
    throw plugin::FrameError("pass '" + passName() + "' needs the renderer state '" + key +
                             "', which nothing provided (Renderer::provideState)");
  return it->second.get();
}

}  // namespace sg::render
