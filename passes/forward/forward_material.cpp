#include "forward_material.hpp"

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

#include <shadelgraph/render/light_binding.hpp>
#include <shadelgraph/render/material_variants.hpp>
#include <shadelgraph/render/environment_binding.hpp>
#include <shadelgraph/render/shadow_binding.hpp>

#include "material_variant.hpp"

namespace sg::passes {
namespace {

const gpu::Pipeline& forwardPipeline(PassContext& ctx, const render::SceneView& view,
                                     const plugin::MaterialStack& material, bool blend, bool plain, bool alphaTest) {
  const render::TextureSet* textures = view.layerTextures.forMaterial(material);
  const ForwardFrameFeatures frame{.shadowMaps = view.frameImages.count(render::kShadowMapsResource) != 0,
                                   .lightGrid = view.frameImages.count(render::kLightGridResource) != 0,
                                   .environmentMaps = view.frameImages.count(render::kEnvironmentSpecularResource) != 0};
  const auto describe = [&] {
    gpu::GraphicsPipelineDesc desc = forwardMaterialPipeline(view.materials, material, blend, plain, frame, alphaTest);
    desc.layout.extraSets.push_back(view.scene.materialSetLayout());
    if (textures) desc.layout.extraSets.push_back(textures->layout());
    return desc;
  };
  try {
    return ctx.device().pipeline(std::string(blend ? "forward/blend/" : "forward/") + (plain ? "plain/" : "") +
                                     (alphaTest ? "alpha-test/" : "") + frame.key() + material.name,
                                 describe);
  } catch (const gpu::ShaderCompileError& e) {
    throw render::layerCompileError(e, ctx.device().shaders(), "the forward variant of material '" + material.name + "'",
                                    material.plugin);
  }
}

// The frame uniforms and the frame resources the material's layers sample.
std::vector<gpu::DescriptorWrite> forwardDescriptors(PassContext& ctx, const render::SceneView& view,
                                                     const plugin::MaterialStack& material) {
  std::vector<gpu::DescriptorWrite> writes{{shader::kBindFrame, gpu::BufferBinding{view.frameUniforms.handle()}},
                                           render::shadowMapsWrite(ctx, view)};
  for (const auto& w : render::environmentWrites(ctx, view)) writes.push_back(w);
  for (const auto& write : render::lightWrites(ctx, view)) writes.push_back(write);
  uint32_t binding = render::kBindLayerFrameInputs;
  for (const auto& name : material.layers) {
    const auto& layer = view.materials.layer(name);
    for (const auto& input : layer.frameInputs) {
      const auto image = render::frameInputImage(view.frameImages, layer, input);
      writes.push_back({binding++, gpu::ImageBinding{ctx.image(image).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                     ctx.device().nearestSampler()}});
    }
  }
  return writes;
}

// Draw `d` runs the plain variant: the glTF layer alone (it reads UVs, tangent
// and colour only through textures and COLOR_0, which the draw has none of).
bool plainForward(const render::SceneView& view, uint32_t d) {
  const auto& layers = forwardMaterial(view, d).layers;
  return view.scene.draws()[d].plainSurface && layers.size() == 1 && layers[0] == "gltf-pbr";
}

}  // namespace

std::string ForwardFrameFeatures::key() const {
  return std::string(shadowMaps ? "" : "no-shadows/") + (lightGrid ? "" : "no-grid/") + (environmentMaps ? "" : "no-env/");
}

gpu::GraphicsPipelineDesc forwardMaterialPipeline(const plugin::Registry& registry, const plugin::MaterialStack& material,
                                                  bool blend, bool plain, ForwardFrameFeatures frame, bool alphaTest) {
  std::vector<gpu::DescriptorBinding> bindings{{shader::kBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                               render::shadowMapsBinding()};
  for (const auto& b : render::environmentBindings()) bindings.push_back(b);
  for (const auto& binding : render::lightBindings()) bindings.push_back(binding);
  for (uint32_t i = 0; i < render::forwardFrameInputs(registry, material).size(); ++i)
    bindings.push_back({render::kBindLayerFrameInputs + i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER});
  gpu::ShaderRequest vertex{.path = "passes/forward/forward.vert"};
  if (plain) vertex.defines.push_back({"SG_FORWARD_PLAIN", "1"});
  gpu::ShaderRequest fragment = forwardMaterialVariant(registry, material, plain, alphaTest);
  if (!frame.shadowMaps) fragment.defines.push_back({"SG_NO_SHADOW_MAPS", "1"});
  if (!frame.lightGrid) fragment.defines.push_back({"SG_NO_LIGHT_GRID", "1"});
  if (!frame.environmentMaps) fragment.defines.push_back({"SG_NO_ENVIRONMENT_MAPS", "1"});
  return {.vertex = vertex,
          .fragment = fragment,
          .layout = {.bindings = bindings, .pushConstantBytes = sizeof(render::ObjectConstants)},
          .vertexInput = render::sceneVertexInput(),
          .colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT},
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = !blend,
          .alphaBlend = blend};
}

void readFrameInputs(graph::Pass& pass, const render::SceneView& view, std::span<const uint32_t> draws) {
  render::readShadowMaps(pass, view, graph::ShaderStage::Fragment);
  render::readEnvironment(pass, view, graph::ShaderStage::Fragment);
  render::readLightGrid(pass, view, graph::ShaderStage::Fragment);
  std::set<const plugin::MaterialStack*> materials;
  for (uint32_t d : draws) materials.insert(&forwardMaterial(view, d));
  for (const auto* material : materials)
    for (const auto& name : material->layers) {
      const auto& layer = view.materials.layer(name);
      for (const auto& input : layer.frameInputs)
        pass.read(render::frameInputImage(view.frameImages, layer, input), graph::Access::Sampled,
                  graph::ShaderStage::Fragment);
    }
}

const plugin::MaterialStack& forwardMaterial(const render::SceneView& view, uint32_t draw) {
  return view.materials.materialFor(view.scene.draws()[draw].materialStack, plugin::ShadingPath::Forward);
}

std::vector<uint32_t> drawsWithAlphaMode(const render::SceneView& view, scene::AlphaMode mode) {
  // Grouped by (material, variant) so that drawForward binds each pipeline once;
  // the keys are looked up once per draw, not per comparison.
  struct Keyed {
    const std::string* material;
    bool plain;
    uint32_t draw;
  };
  std::vector<Keyed> keyed;
  for (uint32_t d : view.draws)
    if (view.scene.draws()[d].alphaMode == mode) keyed.push_back({&forwardMaterial(view, d).name, plainForward(view, d), d});
  std::stable_sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
    return std::tie(*a.material, a.plain) < std::tie(*b.material, b.plain);
  });
  std::vector<uint32_t> draws;
  draws.reserve(keyed.size());
  for (const auto& k : keyed) draws.push_back(k.draw);
  return draws;
}

void drawForward(PassContext& ctx, const render::SceneView& view, std::span<const uint32_t> draws, bool blend,
                 OverdrawCounter counter) {
  view.scene.bindGeometry(ctx.cmd());
  // The pipeline (looked up by name) and its texture set change only with the
  // material, and the draws come grouped by material.
  const plugin::MaterialStack* boundMaterial = nullptr;
  bool boundPlain = false, boundAlphaTest = false;
  const gpu::Pipeline* pipeline = nullptr;
  for (uint32_t d : draws) {
    const auto& material = forwardMaterial(view, d);
    const bool plain = plainForward(view, d);
    const bool alphaTest = view.scene.draws()[d].alphaMode == scene::AlphaMode::Mask;
    if (&material != boundMaterial || plain != boundPlain || alphaTest != boundAlphaTest) {
      pipeline = &forwardPipeline(ctx, view, material, blend, plain, alphaTest);
      const auto writes = forwardDescriptors(ctx, view, material);
      ctx.bind(*pipeline, writes);
      if (const render::TextureSet* textures = view.layerTextures.forMaterial(material)) {
        VkDescriptorSet set = textures->set();
        vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->layout(), render::kLayerTextureSet,
                                1, &set, 0, nullptr);
      }
      boundMaterial = &material;
      boundPlain = plain;
      boundAlphaTest = alphaTest;
    }
    const auto& item = view.scene.draws()[d];
    VkDescriptorSet set = view.scene.materialSet(item.material);
    vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline->layout(), 1, 1, &set, 0, nullptr);
    if (d == draws.front()) counter.begin(ctx.cmd());  // once every set is bound (overdraw_probe.hpp)
    render::drawItem(ctx.cmd(), *pipeline, view, d, d);
  }
  if (!draws.empty()) counter.end(ctx.cmd());
}

bool hasAlphaMode(const render::SceneView& view, scene::AlphaMode mode) {
  return std::any_of(view.draws.begin(), view.draws.end(),
                     [&](uint32_t d) { return view.scene.draws()[d].alphaMode == mode; });
}

}  // namespace sg::passes
