#include "composite.hpp"

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

#include <shadelgraph/gpu/pass_context.hpp>

#include "shadel-gutter/shadel_gutter.hpp"

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindFrame,           kBindParams,      kBindObjects,         kBindShadelInstances,
                               kBindLevelRectTexels, kBindRemapTexels, kBindChunkSlotTexels, kBindCounters,
                               kBindLayerImage};
}  // namespace

bool countsPerSubgroup(VkPhysicalDevice physicalDevice) {
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES, &subgroup};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(physicalDevice, &properties);
  return driver.driverID == VK_DRIVER_ID_MESA_LLVMPIPE && (subgroup.supportedStages & VK_SHADER_STAGE_FRAGMENT_BIT) &&
         (subgroup.supportedOperations & VK_SUBGROUP_FEATURE_BALLOT_BIT);
}

gpu::GraphicsPipelineDesc compositePipeline(int filter, bool levelView, bool alphaTest, VkDescriptorSetLayout materialSet,
                                            uint32_t levelRule, bool countPerSubgroup) {
  std::vector<std::pair<std::string, std::string>> defines{filterDefine(filter)};
  if (levelView) defines.emplace_back("SG_VIEW_LEVEL", "1");
  if (countPerSubgroup) defines.emplace_back("SG_COUNT_PER_SUBGROUP", "1");
  for (auto& define : levelRuleDefines(levelRule)) defines.push_back(std::move(define));
  std::vector<std::pair<std::string, std::string>> vertexDefines;
  if (alphaTest) {
    defines.emplace_back("SG_ALPHA_TEST", "1");
    vertexDefines.emplace_back("SG_ALPHA_TEST", "1");
  }
  return {.vertex = {.path = "passes/composite/composite.vert", .defines = vertexDefines},
          .fragment = {.path = "passes/composite/composite.frag", .defines = defines},
          .layout = alphaTest ? decoupledLayout(kBindings, false, sizeof(render::ObjectConstants), {materialSet})
                              : decoupledLayout(kBindings, false, sizeof(render::ObjectConstants)),
          .vertexInput = render::sceneVertexInput(),
          .colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT},
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          // Opaque: of fragments tied in depth only the first draws: biased
          // one unit nearer, it passes LESS against the depth pre-pass's value
          // and writes its own, which the next tied fragment does not pass.
          // The opaque draws go in reverse order, so across draws that is the
          // last-drawn one, as forward's EQUAL test keeps. Alpha-tested: the
          // early depth write would land before the alpha test discards, so
          // none, and LESS_OR_EQUAL: every tied fragment draws (the last one
          // shows), but none where an opaque one took the pixel. The depth
          // pre-pass's requests keep the same fragments (drawMarkRequests), so
          // their chunks are the ones marked.
          .depthTest = true,
          .depthWrite = !alphaTest,
          .depthCompare = alphaTest ? VK_COMPARE_OP_LESS_OR_EQUAL : VK_COMPARE_OP_LESS,
          .depthBias = -1.0f};
}

CompositeOutput addComposite(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle color,
                             graph::ResourceHandle depth, std::optional<VkClearColorValue> clear) {
  // Composite reads exactly the footprint shadel-mark marked for its filter:
  // any other filter would read unmarked shadels (misses).
  if (frame.markedFilter >= 0 && frame.markedFilter != frame.filter)
    throw std::logic_error("composite filter " + std::to_string(frame.filter) + " differs from shadel-mark's " +
                           std::to_string(frame.markedFilter));
  // Each level's footprint is read from one chunk tile: fill the tiles' gutters first.
  addShadelGutter(graph, frame);
  auto& pass = graph.addPass("composite", graph::QueueClass::Graphics);
  if (!clear) pass.read(color, graph::Access::ColorAttachmentRead);
  depth = pass.write(depth, graph::Access::DepthAttachment);
  // Both through texel views (composite.frag).
  pass.read(frame.remap, graph::Access::Sampled, graph::ShaderStage::Fragment);
  pass.read(frame.slots, graph::Access::Sampled, graph::ShaderStage::Fragment);
  pass.read(frame.shadedColor, graph::Access::Sampled);
  render::readSceneGeometry(pass, frame.view);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);  // misses
  color = pass.write(color, graph::Access::ColorAttachment);
  // Culled draws (instance count 0 in the frame's draw commands) are skipped.
  pass.execute([indirect = render::readDrawCommands(pass, frame.view).indirect, frame, color, depth,
                clear](PassContext& ctx) {
    ctx.beginRendering({ColorTarget{color, clear}}, DepthTarget{depth, {}}, true);
    drawDecoupled(ctx, frame, kBindings, indirect, [&](bool alphaTest, uint32_t levelRule) -> const gpu::Pipeline& {
      const std::string variant = std::to_string(frame.filter) + (frame.levelView ? "/level" : "") +
                                  (alphaTest ? "/alpha-test" : "") + levelRuleVariant(levelRule);
      return ctx.device().pipeline("composite/" + variant, [&] {
        return compositePipeline(frame.filter, frame.levelView, alphaTest, frame.view.scene.materialSetLayout(),
                                 levelRule, countsPerSubgroup(ctx.device().context().physicalDevice()));
      });
    }, /*reverseOpaque=*/true);
    ctx.endRendering();
  });
  return {color, depth};
}

}  // namespace sg::passes
