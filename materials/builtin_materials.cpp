#include "builtin_materials.hpp"

#include <shadelgraph/render/gltf_material_stack.hpp>

namespace sg::materials {

using plugin::LayerDependence;
using plugin::LayerPaths;
using plugin::MaterialLayer;
using plugin::MaterialStack;

namespace {

// The glTF material extensions as layers on gltf-pbr: one material per
// combination, named as render::gltfMaterialStack names them, which is what a
// glTF material using them runs. Each extension layer is named after the
// material it completes ("gltf-pbr-sheen" is the sheen over gltf-pbr) and
// reads the layer under it, a parameter of its one GLSL source.
void registerGltfExtensionMaterials(plugin::Registry& registry) {
  // KHR_materials_ior / _specular: the dielectric Fresnel, an input under the base.
  registry.addLayer({.name = "dielectric-specular", .source = "materials/khr/dielectric_specular.glsl",
                     .function = "dielectricSpecular", .dependsOn = LayerDependence::Surface});
  registry.addLayer({.name = "gltf-pbr-specular", .source = "materials/khr/gltf_pbr_specular.glsl",
                     .function = "shadeGltfPbrSpecular", .reads = {{"dielectric-specular", 0}}});
  for (const bool specular : {false, true})
    for (const bool sheen : {false, true})
      for (const bool clearcoat : {false, true}) {
        if (!sheen && !clearcoat) {
          if (specular) registry.addMaterial({.name = "gltf-pbr-specular", .layers = {"dielectric-specular", "gltf-pbr-specular"}});
          continue;
        }
        std::vector<std::string> layers =
            specular ? std::vector<std::string>{"dielectric-specular", "gltf-pbr-specular"} : std::vector<std::string>{"gltf-pbr"};
        const auto stackOn = [&](const std::string& name, const char* source, const char* function, const char* base) {
          if (!registry.hasLayer(name))
            registry.addLayer({.name = name, .source = source, .function = function, .reads = {{layers.back(), 0}},
                               .parameters = {{base, plugin::glslName(layers.back())}}});
          layers.push_back(name);
        };
        if (sheen)
          stackOn(render::gltfMaterialStack({.specular = specular, .sheen = true}), "materials/khr/sheen.glsl",
                  "sheenLayer", "SHEEN_BASE");
        if (clearcoat)
          stackOn(render::gltfMaterialStack({.specular = specular, .sheen = sheen, .clearcoat = true}),
                  "materials/khr/clearcoat.glsl", "clearcoatLayer", "CLEARCOAT_BASE");
        registry.addMaterial({.name = render::gltfMaterialStack({specular, sheen, clearcoat}), .layers = layers});
      }
}

}  // namespace

void registerBuiltinMaterials(plugin::Registry& registry) {
  registry.beginPlugin("built-in");
  // glTF metallic-roughness: the default material of every object.
  registry.addLayer({.name = "gltf-pbr", .source = "materials/gltf-pbr/gltf_pbr.glsl", .function = "shadeGltfPbr"});
  registry.addMaterial({.name = "gltf-pbr", .layers = {"gltf-pbr"}});

  // Height -> normal: a neighbourhood read in shadel space, screen derivatives forward.
  const std::vector<std::pair<std::string, std::string>> bumps{{"BUMP_FREQUENCY", "16.0"}, {"BUMP_HEIGHT", "0.04"}};
  // The height is a function of the texture coordinate alone: kept across shade frames, even while
  // its object moves (docs/authoring-material-layers.md, "Layer rates").
  registry.addLayer({.name = "height", .source = "materials/height-normal/height.glsl", .function = "bumpHeight",
                     .format = graph::Format::R16F, .dependsOn = LayerDependence::Surface, .parameters = bumps});
  registry.addLayer({.name = "normal-from-height", .source = "materials/height-normal/normal_from_height.glsl",
                     .function = "normalFromHeight", .reads = {{"height", 1}}, .paths = LayerPaths::DecoupledOnly});
  registry.addLayer({.name = "normal-from-height-screen",
                     .source = "materials/height-normal/normal_from_height_screen.glsl",
                     .function = "normalFromHeightScreen", .reads = {{"height", 0}},
                     .paths = LayerPaths::ForwardOnly});
  registry.addMaterial({.name = "bumps", .layers = {"height", "normal-from-height"}, .forwardFallback = "bumps-forward"});
  registry.addMaterial({.name = "bumps-forward", .layers = {"height", "normal-from-height-screen"}});

  // A multi-pass blur of the shaded layer (the paper's skin example).
  const auto blur = [&](std::string name, std::string input, std::string axis) {
    registry.addLayer({.name = std::move(name), .source = "materials/blur/blur.glsl", .function = "blurLayer",
                       .reads = {{input, 2}}, .paths = LayerPaths::DecoupledOnly,
                       .parameters = {{"BLUR_INPUT", plugin::glslName(input)}, {"BLUR_AXIS", std::move(axis)},
                                      {"BLUR_RADIUS", "2"}, {"BLUR_SIGMA", "1.2"}}});
  };
  blur("blur-u", "gltf-pbr", "ivec2(1, 0)");
  blur("blur-v", "blur-u", "ivec2(0, 1)");
  registry.addMaterial({.name = "skin", .layers = {"gltf-pbr", "blur-u", "blur-v"}, .forwardFallback = "gltf-pbr"});

  // A persistent layer: expensive, view-independent, reused from last frame.
  registry.addLayer({.name = "marble", .source = "materials/marble/marble.glsl", .function = "marbleColor",
                     .persistent = true, .parameters = {{"MARBLE_OCTAVES", "10"}}});
  registry.addLayer({.name = "marble-shade", .source = "materials/marble/marble_shade.glsl",
                     .function = "shadeMarble", .reads = {{"marble", 0}}});
  registry.addMaterial({.name = "marble", .layers = {"marble", "marble-shade"}});

  // glTF PBR split at the view: the diffuse part (lights and environment, no
  // camera) is kept across shade frames while its object stays put; the
  // specular part on top follows the shade frame.
  registry.addLayer({.name = "diffuse-light", .source = "materials/split-pbr/diffuse_light.glsl",
                     .function = "diffuseLight", .dependsOn = LayerDependence::World});
  registry.addLayer({.name = "specular-light", .source = "materials/split-pbr/specular_light.glsl",
                     .function = "specularLight", .reads = {{"diffuse-light", 0}}});
  registry.addMaterial({.name = "split-pbr", .layers = {"diffuse-light", "specular-light"}});

  registerGltfExtensionMaterials(registry);

  // Debug layers, each a material of its own.
  for (const auto& [name, source, function] :
       {std::tuple{"uv-checker", "materials/debug/uv_checker.glsl", "uvChecker"},
        std::tuple{"detail-level", "materials/debug/detail_level.glsl", "detailLevelColor"},
        std::tuple{"triangle-id", "materials/debug/triangle_id.glsl", "triangleIdColor"}}) {
    registry.addLayer({.name = name, .source = source, .function = function});
    registry.addMaterial({.name = std::string("debug-") + name, .layers = {name}});
  }
}

const plugin::Registry& builtinMaterials() {
  static const plugin::Registry registry = [] {
    plugin::Registry r;
    registerBuiltinMaterials(r);
    r.check();
    return r;
  }();
  return registry;
}

}  // namespace sg::materials
