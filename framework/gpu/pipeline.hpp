#pragma once
// Compute and graphics pipelines (dynamic rendering, no render passes) with
// explicit descriptor-set layouts, built through the shader compiler and the
// persisted pipeline cache.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <shadelgraph/gpu/shader_compiler.hpp>

namespace sg::gpu {

class Context;
class PipelineCache;

struct DescriptorBinding {
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  VkShaderStageFlags stages = VK_SHADER_STAGE_ALL;
  uint32_t count = 1;
};

struct PipelineLayoutDesc {
  std::vector<DescriptorBinding> bindings;       // set 0, owned by the pipeline
  std::vector<VkDescriptorSetLayout> extraSets;  // sets 1.., owned elsewhere (e.g. materials)
  uint32_t pushConstantBytes = 0;                // visible to all stages
};

struct VertexInput {
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
};

struct GraphicsPipelineDesc {
  ShaderRequest vertex;
  ShaderRequest fragment;  // path empty: depth-only
  PipelineLayoutDesc layout;
  VertexInput vertexInput;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  std::vector<VkFormat> colorFormats;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  bool depthTest = false;
  bool depthWrite = false;
  VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
  // Constant depth bias in the format's units (minimum resolvable differences); 0: none.
  float depthBias = 0.0f;
  bool alphaBlend = false;                                    // premultiplied "over"
  std::string name;
};

struct ComputePipelineDesc {
  ShaderRequest shader;
  PipelineLayoutDesc layout;
  std::string name;
};

// A pipeline with its layout and set-0 layout. Move-only.
class Pipeline {
 public:
  Pipeline() = default;
  Pipeline(const Context& context, ShaderCompiler& compiler, const PipelineCache& cache, const ComputePipelineDesc& desc);
  Pipeline(const Context& context, ShaderCompiler& compiler, const PipelineCache& cache, const GraphicsPipelineDesc& desc);
  ~Pipeline();
  Pipeline(Pipeline&& other) noexcept;
  Pipeline& operator=(Pipeline&& other) noexcept;

  VkPipeline handle() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSetLayout setLayout() const { return setLayout_; }
  VkPipelineBindPoint bindPoint() const { return bindPoint_; }
  const std::vector<DescriptorBinding>& bindings() const { return bindings_; }

 private:
  void createLayout(const PipelineLayoutDesc& desc);
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  std::vector<DescriptorBinding> bindings_;
};

}  // namespace sg::gpu
