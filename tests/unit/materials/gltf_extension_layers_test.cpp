// glTF material extensions into layer stacks, without a device: each test
// asset (tests/assets/khr-materials) loads into its Material fields and
// textures, and picks the built-in stack of gltf-pbr plus one layer per
// extension, in the physical order; bad values are refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <builtin_materials.hpp>
#include <shadelgraph/render/gltf_material_stack.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

namespace sg {
namespace {

const std::filesystem::path kAssets = std::filesystem::path(SG_SOURCE_DIR) / "tests/assets/khr-materials";

std::vector<std::string> layersOf(const std::string& material) {
  return materials::builtinMaterials().material(material).layers;
}

scene::Material onlyMaterial(const std::string& asset) {
  const scene::Scene s = scene::loadGltf(kAssets / (asset + ".gltf"));
  EXPECT_EQ(s.materials.size(), 1u);
  return s.materials.at(0);
}

TEST(GltfExtensionLayers, ClearcoatAssetParsesIntoTheClearcoatStack) {
  const scene::Material m = onlyMaterial("clearcoat");
  ASSERT_TRUE(m.clearcoat.has_value());
  EXPECT_FALSE(m.sheen || m.specular || m.ior);
  EXPECT_FLOAT_EQ(m.clearcoat->factor, 1.0f);
  EXPECT_FLOAT_EQ(m.clearcoat->roughnessFactor, 0.3f);
  EXPECT_TRUE(m.clearcoat->texture.present());
  EXPECT_TRUE(m.clearcoat->roughnessTexture.present());
  EXPECT_TRUE(m.clearcoat->normalTexture.present());
  EXPECT_EQ(render::gltfMaterialStack(m), "gltf-pbr-clearcoat");
  EXPECT_EQ(layersOf("gltf-pbr-clearcoat"), (std::vector<std::string>{"gltf-pbr", "gltf-pbr-clearcoat"}));
}

TEST(GltfExtensionLayers, ClearcoatNormalMapGetsTangents) {
  // No base normal map, no TANGENT: the clear coat's normal map needs MikkTSpace tangents all the same.
  const scene::Scene s = scene::loadGltf(kAssets / "clearcoat.gltf");
  ASSERT_FALSE(s.meshes.empty());
  EXPECT_FALSE(s.meshes[0].primitives[0].tangents.empty());
}

TEST(GltfExtensionLayers, SheenAssetParsesIntoTheSheenStack) {
  const scene::Material m = onlyMaterial("sheen");
  ASSERT_TRUE(m.sheen.has_value());
  EXPECT_FALSE(m.clearcoat || m.specular || m.ior);
  EXPECT_EQ(m.sheen->colorFactor, glm::vec3(1.0f, 0.9f, 0.8f));
  EXPECT_FLOAT_EQ(m.sheen->roughnessFactor, 0.5f);
  EXPECT_TRUE(m.sheen->colorTexture.present());
  EXPECT_TRUE(m.sheen->roughnessTexture.present());
  const scene::Scene s = scene::loadGltf(kAssets / "sheen.gltf");
  EXPECT_TRUE(s.textures[size_t(m.sheen->colorTexture.texture)].srgb) << "sheenColorTexture is colour";
  EXPECT_FALSE(s.textures[size_t(m.sheen->roughnessTexture.texture)].srgb);
  EXPECT_EQ(render::gltfMaterialStack(m), "gltf-pbr-sheen");
  EXPECT_EQ(layersOf("gltf-pbr-sheen"), (std::vector<std::string>{"gltf-pbr", "gltf-pbr-sheen"}));
}

TEST(GltfExtensionLayers, SpecularAssetParsesIntoTheDielectricFresnelUnderTheBase) {
  const scene::Material m = onlyMaterial("specular");
  ASSERT_TRUE(m.specular.has_value());
  EXPECT_FALSE(m.clearcoat || m.sheen || m.ior);
  EXPECT_FLOAT_EQ(m.specular->factor, 1.0f);
  EXPECT_EQ(m.specular->colorFactor, glm::vec3(6.0f, 2.0f, 0.25f));
  EXPECT_TRUE(m.specular->texture.present());
  EXPECT_TRUE(m.specular->colorTexture.present());
  EXPECT_EQ(render::gltfMaterialStack(m), "gltf-pbr-specular");
  EXPECT_EQ(layersOf("gltf-pbr-specular"), (std::vector<std::string>{"dielectric-specular", "gltf-pbr-specular"}));
}

TEST(GltfExtensionLayers, IorAssetUsesTheSpecularStack) {
  const scene::Material m = onlyMaterial("ior");
  ASSERT_TRUE(m.ior.has_value());
  EXPECT_FLOAT_EQ(*m.ior, 2.4f);
  EXPECT_FALSE(m.clearcoat || m.sheen || m.specular);
  EXPECT_EQ(render::gltfMaterialStack(m), "gltf-pbr-specular") << "the ior is the dielectric Fresnel's input too";
}

TEST(GltfExtensionLayers, NoExtensionIsPlainGltfPbr) {
  EXPECT_EQ(render::gltfMaterialStack(scene::Material{}), "gltf-pbr");
}

TEST(GltfExtensionLayers, UnlitWinsOverLitExtensions) {
  scene::Material m;
  m.unlit = true;
  m.clearcoat = scene::Clearcoat{};
  m.sheen = scene::Sheen{};
  EXPECT_EQ(render::gltfMaterialStack(m), "gltf-pbr");
}

TEST(GltfExtensionLayers, EveryCombinationIsRegisteredInPhysicalOrder) {
  // The dielectric Fresnel under the base, sheen on it, the coat on top; each layer reads the one before.
  const plugin::Registry& registry = materials::builtinMaterials();
  for (const bool specular : {false, true})
    for (const bool sheen : {false, true})
      for (const bool clearcoat : {false, true}) {
        const std::string name = render::gltfMaterialStack({specular, sheen, clearcoat});
        SCOPED_TRACE(name);
        ASSERT_TRUE(registry.hasMaterial(name));
        const auto& layers = registry.material(name).layers;
        ASSERT_EQ(layers.size(), size_t(1 + specular + sheen + clearcoat));
        EXPECT_EQ(layers.back(), name) << "an extension layer is named after the material it completes";
        for (size_t i = 1; i < layers.size(); ++i) {
          const auto& reads = registry.layer(layers[i]).reads;
          ASSERT_EQ(reads.size(), 1u) << layers[i];
          EXPECT_EQ(reads[0].layer, layers[i - 1]);
          EXPECT_EQ(reads[0].radius, 0u) << "a point read: the layer runs forward too";
        }
        if (sheen) {
          EXPECT_NE(std::find(layers.begin(), layers.end(), render::gltfMaterialStack({specular, true, false})), layers.end());
        }
      }
  EXPECT_TRUE(registry.layer("dielectric-specular").viewIndependent()) << "a function of the surface's textures";
}

// A one-triangle file whose material carries `extensions`.
std::filesystem::path writeWithMaterialExtensions(const std::string& name, const std::string& extensions) {
  const auto file = std::filesystem::temp_directory_path() / ("sg-khr-" + name + ".gltf");
  std::ofstream(file) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "materials": [{"extensions": )" << extensions << R"(}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
  return file;
}

TEST(GltfExtensionLayers, AllFourStackInOneMaterial) {
  const auto file = writeWithMaterialExtensions("all", R"({"KHR_materials_ior": {"ior": 1.33},
      "KHR_materials_specular": {"specularFactor": 0.5}, "KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1]},
      "KHR_materials_clearcoat": {"clearcoatFactor": 0.5}})");
  const scene::Material m = scene::loadGltf(file).materials.at(0);
  std::filesystem::remove(file);
  EXPECT_FLOAT_EQ(*m.ior, 1.33f);
  EXPECT_FLOAT_EQ(m.specular->factor, 0.5f);
  EXPECT_EQ(m.specular->colorFactor, glm::vec3(1.0f)) << "the default";
  EXPECT_FLOAT_EQ(m.clearcoat->roughnessFactor, 0.0f) << "the default";
  EXPECT_EQ(render::gltfMaterialStack(m), "gltf-pbr-specular-sheen-clearcoat");
  EXPECT_EQ(layersOf("gltf-pbr-specular-sheen-clearcoat"),
            (std::vector<std::string>{"dielectric-specular", "gltf-pbr-specular", "gltf-pbr-specular-sheen",
                                      "gltf-pbr-specular-sheen-clearcoat"}));
}

struct BadValue {
  const char* name;
  const char* extensions;
  const char* expected;
};

class GltfExtensionValues : public ::testing::TestWithParam<BadValue> {};

TEST_P(GltfExtensionValues, AreRefusedByName) {
  const auto file = writeWithMaterialExtensions(GetParam().name, GetParam().extensions);
  try {
    scene::loadGltf(file);
    ADD_FAILURE() << "loaded";
  } catch (const std::exception& error) {
    EXPECT_NE(std::string(error.what()).find(GetParam().expected), std::string::npos) << error.what();
  }
  std::filesystem::remove(file);
}

INSTANTIATE_TEST_SUITE_P(
    Khr, GltfExtensionValues,
    ::testing::Values(
        BadValue{"IorBelowOne", R"({"KHR_materials_ior": {"ior": 0.5}})", "KHR_materials_ior.ior must be a finite number >= 1"},
        BadValue{"ClearcoatAboveOne", R"({"KHR_materials_clearcoat": {"clearcoatFactor": 2}})",
                 "KHR_materials_clearcoat.clearcoatFactor must be a number from 0 to 1"},
        BadValue{"SheenColourShort", R"({"KHR_materials_sheen": {"sheenColorFactor": [1, 1]}})",
                 "KHR_materials_sheen.sheenColorFactor must be an array of 3 numbers"},
        BadValue{"SpecularColourNegative", R"({"KHR_materials_specular": {"specularColorFactor": [1, -1, 1]}})",
                 "KHR_materials_specular.specularColorFactor[1] must be a number >= 0"},
        BadValue{"MissingTexture", R"({"KHR_materials_clearcoat": {"clearcoatTexture": {"index": 3}}})",
                 "clearcoatTexture: texture 3 does not exist"},
        BadValue{"NotAnObject", R"({"KHR_materials_sheen": 1})", "/extensions/KHR_materials_sheen: expected an object"}),
    [](const ::testing::TestParamInfo<BadValue>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace sg
