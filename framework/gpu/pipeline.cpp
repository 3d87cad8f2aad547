#include <shadelgraph/gpu/pipeline.hpp>

#include <utility>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/gpu/pipeline_cache.hpp>

namespace sg::gpu {
namespace {

// A shader module that lives only while its pipeline is created.
struct ShaderModule {
  VkDevice device;
  VkShaderModule module = VK_NULL_HANDLE;
  ShaderModule(VkDevice d, const std::vector<uint32_t>& spirv) : device(d) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size() * 4;
    info.pCode = spirv.data();
    SG_VK(vkCreateShaderModule(device, &info, nullptr, &module));
  }
  ~ShaderModule() { vkDestroyShaderModule(device, module, nullptr); }
  ShaderModule(const ShaderModule&) = delete;
};

VkPipelineShaderStageCreateInfo stageInfo(VkShaderStageFlagBits stage, VkShaderModule module) {
  VkPipelineShaderStageCreateInfo s{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  s.stage = stage;
  s.module = module;
  s.pName = "main";
  return s;
}

}  // namespace

void Pipeline::createLayout(const PipelineLayoutDesc& desc) {
  bindings_ = desc.bindings;
  std::vector<VkDescriptorSetLayoutBinding> vkBindings;
  for (const auto& b : desc.bindings) vkBindings.push_back({b.binding, b.type, b.count, b.stages, nullptr});
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.bindingCount = static_cast<uint32_t>(vkBindings.size());
  setInfo.pBindings = vkBindings.data();
  SG_VK(vkCreateDescriptorSetLayout(device_, &setInfo, nullptr, &setLayout_));
  VkPushConstantRange push{VK_SHADER_STAGE_ALL, 0, desc.pushConstantBytes};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  std::vector<VkDescriptorSetLayout> sets{setLayout_};
  sets.insert(sets.end(), desc.extraSets.begin(), desc.extraSets.end());
  info.setLayoutCount = static_cast<uint32_t>(sets.size());
  info.pSetLayouts = sets.data();
  info.pushConstantRangeCount = desc.pushConstantBytes ? 1 : 0;
  info.pPushConstantRanges = &push;
  SG_VK(vkCreatePipelineLayout(device_, &info, nullptr, &layout_));
}

Pipeline::Pipeline(const Context& context, ShaderCompiler& compiler, const PipelineCache& cache,
                   const ComputePipelineDesc& desc)
    : device_(context.device()), bindPoint_(VK_PIPELINE_BIND_POINT_COMPUTE) {
  ShaderRequest request = desc.shader;
  request.stage = ShaderStage::Compute;
  ShaderModule module(device_, compiler.compile(request));
  createLayout(desc.layout);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = stageInfo(VK_SHADER_STAGE_COMPUTE_BIT, module.module);
  info.layout = layout_;
  SG_VK(vkCreateComputePipelines(device_, cache.handle(), 1, &info, nullptr, &pipeline_));
  context.setDebugName(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(pipeline_), desc.name.c_str());
}

Pipeline::Pipeline(const Context& context, ShaderCompiler& compiler, const PipelineCache& cache,
                   const GraphicsPipelineDesc& desc)
    : device_(context.device()), bindPoint_(VK_PIPELINE_BIND_POINT_GRAPHICS) {
  ShaderRequest vs = desc.vertex;
  vs.stage = ShaderStage::Vertex;
  ShaderModule vertex(device_, compiler.compile(vs));
  std::optional<ShaderModule> fragment;
  std::vector<VkPipelineShaderStageCreateInfo> stages{stageInfo(VK_SHADER_STAGE_VERTEX_BIT, vertex.module)};
  if (!desc.fragment.path.empty()) {
    ShaderRequest fs = desc.fragment;
    fs.stage = ShaderStage::Fragment;
    fragment.emplace(device_, compiler.compile(fs));
    stages.push_back(stageInfo(VK_SHADER_STAGE_FRAGMENT_BIT, fragment->module));
  }
  createLayout(desc.layout);

  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = static_cast<uint32_t>(desc.vertexInput.bindings.size());
  vertexInput.pVertexBindingDescriptions = desc.vertexInput.bindings.data();
  vertexInput.vertexAttributeDescriptionCount = static_cast<uint32_t>(desc.vertexInput.attributes.size());
  vertexInput.pVertexAttributeDescriptions = desc.vertexInput.attributes.data();
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = desc.topology;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.frontFace = desc.frontFace;  // ignored: front face is dynamic state (set per draw)
  raster.lineWidth = 1.0f;
  raster.depthBiasEnable = desc.depthBias != 0.0f;
  raster.depthBiasConstantFactor = desc.depthBias;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = desc.depthTest;
  depth.depthWriteEnable = desc.depthWrite;
  depth.depthCompareOp = desc.depthCompare;
  std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colorFormats.size());
  for (auto& b : blends) {
    b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                       VK_COLOR_COMPONENT_A_BIT;
    if (desc.alphaBlend) {
      b.blendEnable = VK_TRUE;
      b.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
      b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      b.colorBlendOp = VK_BLEND_OP_ADD;
      b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
      b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
      b.alphaBlendOp = VK_BLEND_OP_ADD;
    }
  }
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = static_cast<uint32_t>(blends.size());
  blend.pAttachments = blends.data();
  // Cull mode is dynamic so one pipeline draws single- and double-sided
  // materials; front face so it draws mirrored instances (negative determinant).
  VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR, VK_DYNAMIC_STATE_CULL_MODE,
                                    VK_DYNAMIC_STATE_FRONT_FACE};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 4;
  dynamic.pDynamicStates = dynamicStates;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<uint32_t>(desc.colorFormats.size());
  rendering.pColorAttachmentFormats = desc.colorFormats.data();
  rendering.depthAttachmentFormat = desc.depthFormat;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.pNext = &rendering;
  info.stageCount = static_cast<uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_;
  SG_VK(vkCreateGraphicsPipelines(device_, cache.handle(), 1, &info, nullptr, &pipeline_));
  context.setDebugName(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<uint64_t>(pipeline_), desc.name.c_str());
}

Pipeline::~Pipeline() { release(); }

Pipeline::Pipeline(Pipeline&& o) noexcept { *this = std::move(o); }

Pipeline& Pipeline::operator=(Pipeline&& o) noexcept {
  if (this != &o) {
    release();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    pipeline_ = std::exchange(o.pipeline_, VK_NULL_HANDLE);
    layout_ = std::exchange(o.layout_, VK_NULL_HANDLE);
    setLayout_ = std::exchange(o.setLayout_, VK_NULL_HANDLE);
    bindPoint_ = o.bindPoint_;
    bindings_ = std::move(o.bindings_);
  }
  return *this;
}

void Pipeline::release() {
  if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (setLayout_) vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
}

}  // namespace sg::gpu
