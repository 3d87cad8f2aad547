// A well-formed plugin: a layer, a material using it, and a post pass whose
// declare function (plugin code) calls RenderGraph::addPass (framework code,
// which must be the host's).
#include <filesystem>

#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/plugin/plugin_api.hpp>

namespace {

void registerGood(sg::plugin::Registry* registry, const char* directory) {
  registry->addShaderDirectory(std::filesystem::path(directory) / "shaders");
  registry->addLayer({.name = "test-layer", .source = "test/layer.glsl", .function = "testLayer"});
  registry->addMaterial({.name = "test-material", .layers = {"test-layer"}});
  registry->addPostPass({.name = "test-post",
                         .declare = [](sg::graph::RenderGraph& graph, sg::graph::ResourceHandle color) {
                           auto& pass = graph.addPass("test-post", sg::graph::QueueClass::Graphics);
                           pass.read(color, sg::graph::Access::Sampled, sg::graph::ShaderStage::Fragment);
                           pass.sideEffect();  // like a histogram sent elsewhere: kept though nothing reads it
                           pass.execute([](sg::PassContext&) {});
                           return color;
                         }});
}

}  // namespace

SG_PLUGIN("test-good", registerGood)
