#pragma once
// A pass plugin: what a render pass registers so that frames can name it.
// Built-in passes (plugins/forward, plugins/decoupled) and passes from plugin
// libraries register the same way. A pass reads and writes named frame
// resources ("scene.depth", "scene.hdr", "scene.ldr", "view.draws", a plugin's
// own "ao.image"...); frames are composed from these names alone.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadelgraph/graph/queue.hpp>

namespace sg::render {
class FrameContext;
}

namespace sg::plugin {

struct PassParameter {
  std::string name;
  nlohmann::json defaultValue;  // also its type: a frame's value must have the same JSON type
  std::string description;
};

struct PassPlugin {
  std::string name;
  std::string description;
  graph::QueueClass queue = graph::QueueClass::Graphics;
  std::vector<std::string> reads;   // frame resources it needs written by an earlier pass (or the renderer)
  std::vector<std::string> writes;  // frame resources it creates or gives a new version
  std::vector<PassParameter> parameters;
  // Called for every pass of the frame, in order, before any pass declares:
  // where a package sets up what its passes share (which draws it takes).
  std::function<void(render::FrameContext&)> prepare;
  // Adds the pass's graph passes (none when the frame has nothing for it) and
  // publishes what it wrote with FrameContext::write.
  std::function<void(render::FrameContext&)> declare;
  std::string plugin;  // filled by the registry
};

// Frame resources the renderer provides before any pass runs.
inline constexpr const char* kOutputResource = "scene.ldr";           // the 8-bit sRGB output image
inline constexpr const char* kForwardDrawsResource = "view.draws";    // visible draws shaded forward
inline constexpr const char* kDecoupledDrawsResource = "view.decoupled";  // visible draws a package shades decoupled
// Only in a frame with a pick pending (RenderSettings::pick): a 4-byte buffer
// that a pick pass (passes/object-pick) writes the object under the pixel to
// (scene instance + 1; 0: none); the renderer reads it back (FrameResult::picked).
inline constexpr const char* kPickResource = "view.pick";
bool isRendererResource(const std::string& name);

}  // namespace sg::plugin
