#pragma once
// From render's frame options (RenderArgs) to what sets up the frame: the
// renderer's and decoupled shading's settings and the cameras the options
// name. render and view build their frames through these.
#include <shadelgraph/render/renderer.hpp>

#include <decoupled/decoupled_shading.hpp>

#include "app_session.hpp"
#include "command_options.hpp"

namespace sg::app {

// --view's names, in the order the viewer offers them.
const std::vector<std::pair<std::string, plugins::DebugView>>& debugViews();
plugins::DecoupledSettings decoupledSettings(const RenderArgs& args);
// Size, --camera, aliasing, frames in flight (not the camera path: pathCamera).
render::RenderSettings renderSettings(const RenderArgs& args);
// The camera at frame `frame` (30 per second) of the scene file's camera path `path`.
scene::Camera pathCamera(const AppSession& session, int path, int frame);
// Throws unless the scene has camera `index` (named as the option --camera).
void checkCameraIndex(const AppSession& session, int index);

}  // namespace sg::app
