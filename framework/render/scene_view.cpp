#include <shadelgraph/render/scene_view.hpp>

#include <glm/glm.hpp>

namespace sg::render {

void drawItem(VkCommandBuffer cmd, const gpu::Pipeline& pipeline, const DrawItem& draw, uint32_t objectId) {
  const ObjectConstants constants{draw.world, objectId, draw.material};
  vkCmdPushConstants(cmd, pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof constants, &constants);
  vkCmdSetCullMode(cmd, draw.doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT);
  // A mirroring world matrix turns counter-clockwise triangles clockwise on screen.
  const bool mirrored = glm::determinant(glm::mat3(draw.world)) < 0.0f;
  vkCmdSetFrontFace(cmd, mirrored ? VK_FRONT_FACE_CLOCKWISE : VK_FRONT_FACE_COUNTER_CLOCKWISE);
  vkCmdDrawIndexed(cmd, draw.indexCount, 1, draw.firstIndex, draw.vertexOffset, 0);
}

}  // namespace sg::render
