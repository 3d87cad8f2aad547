#include <shadelgraph/render/scene_view.hpp>

#include <glm/glm.hpp>

namespace sg::render {

SceneView readDrawCommands(graph::Pass& pass, SceneView view) {
  if (view.commands && view.commands->handle.valid()) {
    pass.read(view.commands->handle, graph::Access::IndirectArgs);
    view.indirect = view.commands->buffer;
  }
  return view;
}

void readSceneGeometry(graph::Pass& pass, const SceneView& view, graph::Access access, graph::ShaderStage stages) {
  if (const auto it = view.frameImages.find(kSceneVerticesResource); it != view.frameImages.end())
    pass.read(it->second, access, stages);
}

void drawItem(VkCommandBuffer cmd, const gpu::Pipeline& pipeline, const DrawItem& draw, uint32_t objectId,
              VkBuffer indirect, uint32_t drawIndex, bool hiddenBackFaces) {
  const ObjectConstants constants{draw.world, objectId, draw.material};
  vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof constants, &constants);
  vkCmdSetCullMode(cmd, draw.doubleSided && !hiddenBackFaces ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
  // A mirroring world matrix turns counter-clockwise triangles clockwise on screen.
  const bool mirrored = glm::determinant(glm::mat3(draw.world)) < 0.0f;
  vkCmdSetFrontFace(cmd, mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
  if (indirect)
    vkCmdDrawIndexedIndirect(cmd, indirect, VkDeviceSize(drawIndex) * sizeof(VkDrawIndexedIndirectCommand), 1,
                             sizeof(VkDrawIndexedIndirectCommand));
  else
    vkCmdDrawIndexed(cmd, draw.indexCount, 1, draw.firstIndex, draw.vertexOffset, 0);
}

void drawItem(VkCommandBuffer cmd, const gpu::Pipeline& pipeline, const SceneView& view, uint32_t drawIndex,
              uint32_t objectId) {
  drawItem(cmd, pipeline, view.scene.draws()[drawIndex], objectId, view.indirect, drawIndex,
           backFacesHidden(view, drawIndex));
}

}  // namespace sg::render
