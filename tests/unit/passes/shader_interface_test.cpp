// Every built-in pass shader compiled (glslang, no device) and reflected
// (SPIRV-Cross) against the pipeline description its pass creates it with:
// each set-0 binding a stage uses is declared with the same descriptor type,
// each declared binding is used, and the push-constant block is as large as
// declared. The records of the shared interfaces (framework/*/shaders/*.h)
// have the same size in GLSL as in C++. Drift between a pass's C++ and its
// GLSL fails here, not as a validation message at run time.
#include <spirv_cross/spirv_cross_c.h>

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <set>
#include <string>
#include <vector>

#include <builtin_materials.hpp>
#include <builtin_shaders.hpp>
#include <bloom/bloom.hpp>
#include <composite/composite.hpp>
#include <environment/environment.hpp>
#include <debug-views/debug_views.hpp>
#include <exposure/exposure.hpp>
#include <exposure/exposure_interface.h>
#include <forward/forward_material.hpp>
#include <layer-shade/layer_shade.hpp>
#include <light-cull/light_cull.hpp>
#include <live-entry-blocks/live_entry_blocks.hpp>
#include <object-pick/object_pick.hpp>
#include <shadel-allocate/shadel_allocate.hpp>
#include <shadel-clear/shadel_clear.hpp>
#include <shade-frame/shade_frame_work.hpp>
#include <shadel-gutter/shadel_gutter.hpp>
#include <shadel-mark/shadel_mark.hpp>
#include <shade-reuse/shade_reuse.hpp>
#include <shadows/shadows.hpp>
#include <shadelgraph/gpu/shader_compiler.hpp>
#include <shadelgraph/shadel/level_selection.hpp>
#include <support-expand/support_expand.hpp>
#include <tonemap/tonemap.hpp>
#include <work-aggregate/work_aggregate.hpp>
#include <occlusion-cull/occlusion_cull.hpp>
#include <skinning/skinning.hpp>
#include <z-prepass/z_prepass.hpp>

namespace sg::test {
namespace {

// What a compiled stage uses: its set-0 bindings (by type), the push-constant
// block's size, and the size of every named record a block holds.
struct StageInterface {
  std::map<uint32_t, VkDescriptorType> bindings;
  uint32_t pushConstantBytes = 0;
  std::map<std::string, size_t> records;
};

class Reflection {
 public:
  explicit Reflection(const std::vector<uint32_t>& spirv) {
    check(spvc_context_create(&context_));
    spvc_parsed_ir ir = nullptr;
    check(spvc_context_parse_spirv(context_, spirv.data(), spirv.size(), &ir));
    check(spvc_context_create_compiler(context_, SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler_));
  }
  ~Reflection() { spvc_context_destroy(context_); }
  Reflection(const Reflection&) = delete;
  Reflection& operator=(const Reflection&) = delete;

  // Only what the stage statically uses: a declared, unused binding needs no descriptor.
  StageInterface used() {
    spvc_set active = nullptr;
    check(spvc_compiler_get_active_interface_variables(compiler_, &active));
    spvc_resources resources = nullptr;
    check(spvc_compiler_create_shader_resources_for_active_variables(compiler_, &resources, active));
    StageInterface out;
    const std::pair<spvc_resource_type, VkDescriptorType> kinds[] = {
        {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
        {SPVC_RESOURCE_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
        {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
        {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
        {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE}};
    for (const auto& [kind, type] : kinds)
      for (const spvc_reflected_resource& r : list(resources, kind)) {
        if (spvc_compiler_get_decoration(compiler_, r.id, SpvDecorationDescriptorSet) != 0) continue;
        out.bindings[spvc_compiler_get_decoration(compiler_, r.id, SpvDecorationBinding)] = texelBuffer(r) ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER : type;
        if (type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER)
          addRecords(r.base_type_id, out.records);
      }
    for (const spvc_reflected_resource& r : list(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT)) {
      size_t size = 0;
      check(spvc_compiler_get_declared_struct_size(compiler_, spvc_compiler_get_type_handle(compiler_, r.base_type_id),
                                                   &size));
      out.pushConstantBytes = uint32_t(size);
      addRecords(r.base_type_id, out.records);
    }
    return out;
  }

 private:
  static void check(spvc_result result) {
    if (result != SPVC_SUCCESS) throw std::runtime_error("SPIRV-Cross failed: " + std::to_string(int(result)));
  }
  // A samplerBuffer is a sampled image of dimension Buffer: a uniform texel buffer.
  bool texelBuffer(const spvc_reflected_resource& r) {
    const spvc_type type = spvc_compiler_get_type_handle(compiler_, r.base_type_id);
    const spvc_basetype base = spvc_type_get_basetype(type);
    return (base == SPVC_BASETYPE_SAMPLED_IMAGE || base == SPVC_BASETYPE_IMAGE) &&
           spvc_type_get_image_dimension(type) == SpvDimBuffer;
  }
  std::vector<spvc_reflected_resource> list(spvc_resources resources, spvc_resource_type kind) {
    const spvc_reflected_resource* items = nullptr;
    size_t count = 0;
    check(spvc_resources_get_resource_list_for_type(resources, kind, &items, &count));
    return {items, items + count};
  }
  // The block's members that are named records (Sg...), with their GLSL size.
  void addRecords(spvc_type_id block, std::map<std::string, size_t>& records) {
    spvc_type type = spvc_compiler_get_type_handle(compiler_, block);
    for (unsigned i = 0; i < spvc_type_get_num_member_types(type); ++i) {
      const spvc_type member = spvc_compiler_get_type_handle(compiler_, spvc_type_get_member_type(type, i));
      const spvc_type_id base = spvc_type_get_base_type_id(member);
      const spvc_type record = spvc_compiler_get_type_handle(compiler_, base);
      if (spvc_type_get_basetype(record) != SPVC_BASETYPE_STRUCT) continue;
      size_t size = 0;
      check(spvc_compiler_get_declared_struct_size(compiler_, record, &size));
      records[spvc_compiler_get_name(compiler_, base)] = size;
    }
  }
  spvc_context context_ = nullptr;
  spvc_compiler compiler_ = nullptr;
};

// The records shared with C++, by their GLSL name.
const std::map<std::string, size_t> kSharedRecords = {
    {"SgFrameUniforms", sizeof(shader::SgFrameUniforms)},
    {"SgObjectConstants", sizeof(shader::SgObjectConstants)},
    {"SgDecoupledObject", sizeof(shader::SgDecoupledObject)},
    {"SgShadeCounters", sizeof(shader::SgShadeCounters)},
    {"SgDecoupledParams", sizeof(shader::SgDecoupledParams)},
    {"SgLayerShadePush", sizeof(shader::SgLayerShadePush)},
    {"SgOccupancyPush", sizeof(shader::SgOccupancyPush)},
    {"SgEntrySpan", sizeof(shader::SgEntrySpan)},
    {"SgEntryBlock", sizeof(shader::SgEntryBlock)},
    {"SgEntryBlocksHeader", sizeof(shader::SgEntryBlocksHeader)},
    {"SgEntryBlocksPush", sizeof(shader::SgEntryBlocksPush)},
    {"SgExposure", sizeof(shader::SgExposure)},
    {"SgExposureParams", sizeof(shader::SgExposureParams)},
    {"SgEnvironmentPush", sizeof(shader::SgEnvironmentPush)},
    {"SgBloomPush", sizeof(shader::SgBloomPush)},
    {"Light", sizeof(shader::Light)},
    {"SgLightGridHeader", sizeof(shader::SgLightGridHeader)},
    {"SgLightCullPush", sizeof(shader::SgLightCullPush)},
};

const char* typeName(VkDescriptorType type) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "uniform buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "storage buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "storage image";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "sampled image";
    case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER: return "uniform texel buffer";
    default: return "other";
  }
}

class ShaderInterface : public ::testing::Test {
 protected:
  ShaderInterface() {
    library_.add(gpu::builtinShaders());
    materials::registerBuiltinMaterials(registry_);
  }

  // Every mismatch between the stages of `name` and its declared layout, one
  // per line. Bindings declared but unused are reported by unused(), over all
  // variants of the pass (a variant may leave one out: tonemap's passthrough
  // reads no exposure, most layers no history).
  std::string mismatches(const std::string& name, const std::vector<gpu::ShaderRequest>& stages,
                         const gpu::PipelineLayoutDesc& layout) {
    std::ostringstream out;
    std::map<uint32_t, VkDescriptorType> used;
    uint32_t push = 0;
    for (const auto& stage : stages) {
      if (stage.path.empty()) continue;
      checkedStages_.insert(stage.path);
      Reflection reflection(compiler_.compile(stage));
      const StageInterface s = reflection.used();
      for (const auto& [binding, type] : s.bindings) {
        auto [it, added] = used.emplace(binding, type);
        if (!added && it->second != type)
          out << name << ": binding " << binding << " is a " << typeName(type) << " in " << stage.path << " and a "
              << typeName(it->second) << " in another stage\n";
      }
      push = std::max(push, s.pushConstantBytes);
      for (const auto& [record, size] : s.records) {
        auto shared = kSharedRecords.find(record);
        if (shared != kSharedRecords.end() && shared->second != size)
          out << name << ": " << record << " is " << size << " bytes in " << stage.path << " but "
              << shared->second << " in C++\n";
        if (shared != kSharedRecords.end()) sharedRecordsSeen_.insert(record);
      }
    }
    std::map<uint32_t, VkDescriptorType> declared;
    for (const auto& b : layout.bindings) declared[b.binding] = b.type;
    for (const auto& [binding, type] : used) {
      auto it = declared.find(binding);
      if (it == declared.end())
        out << name << ": the shaders use set 0 binding " << binding << " (" << typeName(type)
            << "), which the pass does not declare\n";
      else if (it->second != type)
        out << name << ": set 0 binding " << binding << " is a " << typeName(type) << " in the shaders but declared a "
            << typeName(it->second) << "\n";
    }
    auto& [passDeclared, passUsed] = passes_[name.substr(0, name.find(' '))];
    for (const auto& [binding, type] : declared) passDeclared[binding] = type;
    for (const auto& [binding, type] : used) passUsed.insert(binding);
    if (push != layout.pushConstantBytes)
      out << name << ": push constants are " << push << " bytes in the shaders but declared "
          << layout.pushConstantBytes << "\n";
    return out.str();
  }
  std::string mismatches(const std::string& name, const gpu::GraphicsPipelineDesc& desc) {
    return mismatches(name, {desc.vertex, desc.fragment}, desc.layout);
  }
  std::string mismatches(const std::string& name, const gpu::ComputePipelineDesc& desc) {
    return mismatches(name, {desc.shader}, desc.layout);
  }

  // Per pass, bindings declared that none of its variants uses.
  std::string unused() const {
    std::ostringstream out;
    for (const auto& [pass, bindings] : passes_)
      for (const auto& [binding, type] : bindings.first)
        if (!bindings.second.count(binding))
          out << pass << ": declares set 0 binding " << binding << " (" << typeName(type)
              << "), which no variant uses\n";
    return out.str();
  }

  gpu::ShaderLibrary library_;
  gpu::ShaderCompiler compiler_{library_, {}};
  plugin::Registry registry_;
  std::set<std::string> checkedStages_;
  std::set<std::string> sharedRecordsSeen_;
  std::map<std::string, std::pair<std::map<uint32_t, VkDescriptorType>, std::set<uint32_t>>> passes_;
};

TEST_F(ShaderInterface, EveryPassShaderMatchesItsDeclaration) {
  std::string errors;
  // shadel-mark's and composite's variant for objects with a level rule.
  const uint32_t kLevelRule = shadel::packLevelRule(shadel::kUnmipmappedLevelRule);
  errors += mismatches("z-prepass", passes::zPrepassPipeline());
  errors += mismatches("z-prepass alpha-test", passes::zPrepassAlphaTestPipeline(VK_NULL_HANDLE));
  errors += mismatches("z-prepass no-value", passes::zPrepassNoValuePipeline());
  errors += mismatches("exposure-meter", passes::exposureMeterPipeline());
  errors += mismatches("exposure", passes::exposurePipeline(false));
  errors += mismatches("exposure manual", passes::exposurePipeline(true));
  errors += mismatches("shadows", passes::shadowMapPipeline());
  errors += mismatches("skinning", passes::skinningPipeline());
  errors += mismatches("environment-prefilter", passes::environmentPrefilterPipeline());
  errors += mismatches("environment-background", passes::environmentBackgroundPipeline());
  errors += mismatches("bloom", passes::bloomPipeline());
  errors += mismatches("light-cull", passes::lightCullPipeline());
  errors += mismatches("hi-z", passes::hiZPipeline());
  errors += mismatches("occlusion-cull", passes::occlusionCullPipeline());
  errors += mismatches("object-pick", passes::objectPickPipeline());
  errors += mismatches("object-pick alpha-test", passes::objectPickAlphaTestPipeline(VK_NULL_HANDLE));
  for (bool passthrough : {false, true})
    errors += mismatches("tonemap", passes::tonemapPipeline(VK_FORMAT_R8G8B8A8_SRGB, passthrough));
  for (bool entries : {false, true}) errors += mismatches("shadel-clear", passes::shadelClearPipeline(entries));
  for (int filter : {0, 1, 2})
    for (bool baseline : {false, true})
      for (bool alphaTest : {false, true})
        for (bool masks : {false, !baseline})  // the baseline mark has no masks
          for (uint32_t rule : {0u, kLevelRule})
            errors += mismatches("shadel-mark filter=" + std::to_string(filter) + (alphaTest ? " alpha-test" : "") +
                                     (masks ? " masks" : "") + passes::levelRuleVariant(rule),
                                 passes::shadelMarkPipeline(filter, baseline, alphaTest, VK_NULL_HANDLE, masks, rule));
  // Requests: bilinear with masks only (passes::markRequestsPossible).
  for (bool alphaTest : {false, true})
    for (uint32_t rule : {0u, kLevelRule})
      errors += mismatches(std::string("shadel-mark requests") + (alphaTest ? " alpha-test" : "") +
                               passes::levelRuleVariant(rule),
                           passes::shadelMarkPipeline(1, false, alphaTest, VK_NULL_HANDLE, true, rule, true));
  errors += mismatches("shadel-mark-requests", passes::shadelMarkRequestsPipeline());
  errors += mismatches("shadel-mark-neighbours", passes::shadelMarkNeighboursPipeline());
  for (bool header : {false, true}) errors += mismatches("live-entry-blocks", passes::liveEntryBlocksPipeline(header));
  for (bool apply : {false, true}) errors += mismatches("support-expand", passes::supportExpandPipeline(apply));
  for (int phase : {1, 2}) errors += mismatches("shadel-allocate", passes::shadelAllocatePipeline(phase));
  errors += mismatches("work-offsets", passes::workOffsetsPipeline());
  errors += mismatches("work-fill", passes::workFillPipeline());
  errors += mismatches("shade-reuse", passes::shadeReusePipeline());
  errors += mismatches("shadel-gutter", passes::shadelGutterPipeline());
  for (int phase : {0, 1}) errors += mismatches("shade-frame-work", passes::shadeFramePhasePipeline(phase));
  errors += mismatches("work-fill SG_SHADE_ALL", passes::shadeFrameFillPipeline());
  for (int filter : {0, 1, 2})
    for (bool levelView : {false, true})
      for (bool alphaTest : {false, true})
        for (uint32_t rule : {0u, kLevelRule})
          errors += mismatches("composite filter=" + std::to_string(filter) + (alphaTest ? " alpha-test" : "") +
                                   passes::levelRuleVariant(rule),
                               passes::compositePipeline(filter, levelView, alphaTest, VK_NULL_HANDLE, rule));
  errors += mismatches("debug-occupancy", passes::occupancyViewPipeline());
  errors += mismatches("debug-sheet", passes::sheetViewPipeline());
  for (const auto& name : registry_.materialNames()) {
    const auto& material = registry_.material(name);
    if (registry_.runsIn(material, plugin::ShadingPath::Decoupled))
      for (const auto& layer : material.layers)
        for (const uint32_t rows : {1u, 8u})
          errors += mismatches("layer-shade of layer " + layer + " rows " + std::to_string(rows),
                               passes::layerShadePipeline(registry_.layer(layer), rows));
    const auto& forward = registry_.materialFor(name, plugin::ShadingPath::Forward);
    for (bool blend : {false, true})
      for (bool plain : {false, true})
        for (bool frameMaps : {false, true})
          for (bool alphaTest : {false, true}) {
            const passes::ForwardFrameFeatures frame{frameMaps, frameMaps, frameMaps};
            errors += mismatches("forward material " + forward.name + (plain ? " (plain) " : " ") +
                                     (alphaTest ? "(alpha-test) " : "") + frame.key(),
                                 passes::forwardMaterialPipeline(registry_, forward, blend, plain, frame, alphaTest));
          }
  }
  EXPECT_EQ(errors, "");
  EXPECT_EQ(unused(), "");

  // Every stage file of a built-in pass was checked (a new pass must be added above).
  std::string unchecked;
  for (const auto& file : gpu::builtinShaders()) {
    const std::string path(file.path);
    const bool stage = path.ends_with(".vert") || path.ends_with(".frag") || path.ends_with(".comp");
    if (stage && !checkedStages_.count(path)) unchecked += "  " + path + "\n";
  }
  EXPECT_EQ(unchecked, "") << "shader stages no pipeline description above covers";
  // And every shared record reached a shader that uses it.
  for (const auto& [record, size] : kSharedRecords) EXPECT_TRUE(sharedRecordsSeen_.count(record)) << record;
}

// The check itself: a layout that drifts from its shaders is reported.
TEST_F(ShaderInterface, ReportsABindingTypePushConstantAndUnusedBindingThatDrift) {
  gpu::ComputePipelineDesc desc = passes::shadelAllocatePipeline();
  ASSERT_EQ(mismatches("shadel-allocate", desc), "");
  desc.layout.bindings.front().type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;  // kBindParams is a uniform buffer
  desc.layout.bindings.push_back({shader::kBindIdMaps, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER});
  desc.layout.pushConstantBytes = 4;  // the shaders push an SgEntrySpan (12 bytes)
  std::string errors = mismatches("shadel-allocate", desc);
  errors += unused();
  EXPECT_NE(errors.find("binding 1 is a uniform buffer in the shaders but declared a storage buffer"), std::string::npos)
      << errors;
  EXPECT_NE(errors.find("declares set 0 binding 10 (storage buffer), which no variant uses"), std::string::npos) << errors;
  EXPECT_NE(errors.find("push constants are 12 bytes in the shaders but declared 4"), std::string::npos) << errors;

  gpu::ComputePipelineDesc missing = passes::shadelAllocatePipeline();
  missing.layout.bindings.pop_back();
  EXPECT_NE(mismatches("shadel-allocate", missing).find("which the pass does not declare"), std::string::npos);
}

}  // namespace
}  // namespace sg::test
