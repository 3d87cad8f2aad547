// A well-formed plugin: a layer, a material using it, a pass whose declare
// function (plugin code) calls RenderGraph::addPass (framework code, which
// must be the host's), and a frame that runs the pass before exposure.
#include <filesystem>

#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/plugin/plugin_api.hpp>
#include <shadelgraph/render/frame_context.hpp>

namespace {

void registerGood(sg::plugin::Registry* registry, const char* directory) {
  registry->addShaderDirectory(std::filesystem::path(directory) / "shaders");
  registry->addLayer({.name = "test-layer", .source = "test/layer.glsl", .function = "testLayer"});
  registry->addMaterial({.name = "test-material", .layers = {"test-layer"}});
  registry->addPass({.name = "test-post",
                     .description = "reads the HDR colour (like a histogram sent elsewhere)",
                     .reads = {"scene.hdr"},
                     .parameters = {{"strength", 1.0, "unused"}},
                     .declare = [](sg::render::FrameContext& ctx) {
                       auto& pass = ctx.graph().addPass("test-post", sg::graph::QueueClass::Graphics);
                       pass.read(ctx.read("scene.hdr"), sg::graph::Access::Sampled, sg::graph::ShaderStage::Fragment);
                       pass.sideEffect();  // kept though nothing reads it
                       pass.execute([](sg::PassContext&) {});
                     }});
  registry->addFrame({.name = "test-frame",
                      .base = "decoupled",
                      .passes = {{.pass = "test-post", .before = {"exposure"}}}});
}

}  // namespace

SG_PLUGIN("test-good", registerGood)
