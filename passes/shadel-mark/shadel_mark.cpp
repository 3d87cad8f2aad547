#include "shadel_mark.hpp"

#include <array>
#include <string>
#include <vector>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindFrame, kBindParams, kBindObjects, kBindShadelInstances, kBindLevelRects, kBindRemap};
}  // namespace

gpu::GraphicsPipelineDesc shadelMarkPipeline(int filter, bool baseline, bool alphaTest, VkDescriptorSetLayout materialSet) {
  std::vector<std::pair<std::string, std::string>> defines{filterDefine(filter)};
  if (baseline) defines.emplace_back("SG_MARK_BASELINE", "1");
  std::vector<std::pair<std::string, std::string>> vertexDefines;
  if (alphaTest) {
    defines.emplace_back("SG_ALPHA_TEST", "1");
    vertexDefines.emplace_back("SG_ALPHA_TEST", "1");
  }
  return {.vertex = {.path = "passes/shadel-mark/shadel_mark.vert", .defines = vertexDefines},
          .fragment = {.path = "passes/shadel-mark/shadel_mark.frag", .defines = defines},
          .layout = alphaTest ? decoupledLayout(kBindings, false, sizeof(render::ObjectConstants), {materialSet})
                              : decoupledLayout(kBindings, false, sizeof(render::ObjectConstants)),
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = false};
}

void addShadelMark(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle depth) {
  auto& pass = graph.addPass("shadel-mark", graph::QueueClass::Graphics);
  pass.read(depth, graph::Access::DepthRead);
  render::readSceneGeometry(pass, frame.view);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
  frame.markedFilter = frame.filter;
  // Culled draws (instance count 0 in the frame's draw commands) are skipped.
  pass.execute([indirect = render::readDrawCommands(pass, frame.view).indirect, frame, depth](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{depth, {}, true}, true);
    drawDecoupled(ctx, frame, kBindings, indirect, [&](bool alphaTest) -> const gpu::Pipeline& {
      const std::string variant =
          std::to_string(frame.filter) + (frame.baseline ? "/baseline" : "") + (alphaTest ? "/alpha-test" : "");
      return ctx.device().pipeline("shadel-mark/" + variant, [&] {
        return shadelMarkPipeline(frame.filter, frame.baseline, alphaTest, frame.view.scene.materialSetLayout());
      });
    });
    ctx.endRendering();
  });
}

}  // namespace sg::passes
