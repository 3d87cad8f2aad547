#pragma once
#include <optional>

#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

struct CompositeOutput {
  graph::ResourceHandle color, depth;
};
// Draws the decoupled objects with their shaded samples (manual trilinear
// through the remap table) over the forward pass's colour. Of fragments tied
// in depth it draws one only, the last-drawn (compositePipeline), and so
// writes the depth. `clear`: the colour is still unwritten (no forward pass
// drew before it), clear it first.
CompositeOutput addComposite(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle color,
                             graph::ResourceHandle depth, std::optional<VkClearColorValue> clear = {});
// filter: 0 point, 1 bilinear, 2 trilinear; levelView shows the detail level
// instead; alphaTest: the variant for alpha-mask objects, `materialSet` (the
// scene material) its set 1; levelRule: the variant for objects with that
// level rule (shadel::packLevelRule; 0 none), as shadel-mark's;
// countPerSubgroup: count the statistics per subgroup (countsPerSubgroup).
gpu::GraphicsPipelineDesc compositePipeline(int filter, bool levelView, bool alphaTest = false,
                                            VkDescriptorSetLayout materialSet = VK_NULL_HANDLE, uint32_t levelRule = 0,
                                            bool countPerSubgroup = false);
// Whether composite counts its statistics per subgroup on this device:
// lavapipe, whose fragment shaders leave uncovered (helper) lanes out of
// subgroup operations (it has no gl_HelperInvocation to tell them apart).
bool countsPerSubgroup(VkPhysicalDevice physicalDevice);

}  // namespace sg::passes
