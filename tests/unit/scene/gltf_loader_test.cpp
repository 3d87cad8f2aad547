// Loading well-formed glTF files: the Khronos sample models and small files
// written by the tests.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include <shadelgraph/scene/gltf_loader.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

using test::samplePath;
using test::TempDir;

constexpr LoadOptions kGeometryOnly{.decodeImages = false};

bool hasWarningContaining(const Scene& scene, std::string_view text) {
  return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                     [&](const std::string& warning) { return warning.find(text) != std::string::npos; });
}

size_t meshTriangles(const Scene& scene) {
  size_t count = 0;
  for (const Mesh& mesh : scene.meshes) count += mesh.triangleCount();
  return count;
}

// Every index the Scene documents as valid is valid, and attribute arrays match.
void expectConsistent(const Scene& scene, const std::string& name) {
  SCOPED_TRACE(name);
  for (const Instance& instance : scene.instances) {
    ASSERT_GE(instance.mesh, 0);
    ASSERT_LT(static_cast<size_t>(instance.mesh), scene.meshes.size());
  }
  for (const Mesh& mesh : scene.meshes)
    for (const Primitive& p : mesh.primitives) {
      ASSERT_GE(p.material, 0);
      ASSERT_LT(static_cast<size_t>(p.material), scene.materials.size());
      const size_t n = p.positions.size();
      EXPECT_EQ(p.normals.size(), n);
      for (size_t size : {p.tangents.size(), p.uv0.size(), p.uv1.size(), p.colors.size()})
        EXPECT_TRUE(size == 0 || size == n);
      EXPECT_EQ(p.indices.size() % 3, 0u);
      for (uint32_t index : p.indices) ASSERT_LT(index, n);
    }
  for (const Material& material : scene.materials)
    for (const TextureRef* ref : {&material.baseColorTexture, &material.metallicRoughnessTexture,
                                  &material.normalTexture, &material.occlusionTexture, &material.emissiveTexture})
      if (ref->present()) {
        ASSERT_LT(static_cast<size_t>(ref->texture), scene.textures.size());
      }
  for (const Texture& texture : scene.textures) {
    ASSERT_GE(texture.sampler, 0);
    ASSERT_LT(static_cast<size_t>(texture.sampler), scene.samplers.size());
  }
}

TEST(GltfLoader, EverySampleModelLoads) {
  SG_REQUIRE_ASSETS();
  size_t files = 0;
  for (const auto& model : std::filesystem::directory_iterator(test::assetsDir())) {
    const std::filesystem::path folder = model.path() / "glTF";
    if (!std::filesystem::is_directory(folder)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
      const std::string extension = entry.path().extension().string();
      if (extension != ".gltf" && extension != ".glb") continue;
      ++files;
      SCOPED_TRACE(entry.path().string());
      Scene scene;
      ASSERT_NO_THROW(scene = loadGltf(entry.path()));
      EXPECT_FALSE(scene.meshes.empty());
      EXPECT_FALSE(scene.instances.empty());
      EXPECT_GT(meshTriangles(scene), 0u);
      expectConsistent(scene, entry.path().filename().string());
      for (const Texture& texture : scene.textures) {
        EXPECT_GT(texture.width, 0u);
        EXPECT_EQ(texture.pixels.size(), size_t{texture.width} * texture.height * 4);
      }
    }
  }
  EXPECT_GE(files, 23u) << "expected the 23 sample models listed in shared/assets/README.md";
}

// The README's numbers count each mesh once: with the node instancing the
// engine draws 121,496 triangles in 115 primitives, the saw 198,470 in 113.
TEST(GltfLoader, KnownTriangleCounts) {
  SG_REQUIRE_ASSETS();
  struct Expected {
    const char* model;
    size_t meshTriangles;
    size_t instancedTriangles;
    size_t primitives;
  };
  for (const Expected& expected : {Expected{"2CylinderEngine", 75'730, 121'496, 34},
                                   Expected{"ReciprocatingSaw", 139'594, 198'470, 65},
                                   Expected{"MetalRoughSpheresNoTextures", 1'040'409, 1'040'409, 123},
                                   Expected{"DamagedHelmet", 15'452, 15'452, 1}}) {
    SCOPED_TRACE(expected.model);
    const Scene scene = loadGltf(samplePath(expected.model), kGeometryOnly);
    size_t primitives = 0;
    for (const Mesh& mesh : scene.meshes) primitives += mesh.primitives.size();
    EXPECT_EQ(meshTriangles(scene), expected.meshTriangles);
    EXPECT_EQ(instancedTriangleCount(scene), expected.instancedTriangles);
    EXPECT_EQ(primitives, expected.primitives);
  }
}

TEST(GltfLoader, NonIndexedTriangleGetsSequentialIndices) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("TriangleWithoutIndices"));
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Primitive& p = scene.meshes[0].primitives.at(0);
  EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(p.positions.size(), 3u);
}

TEST(GltfLoader, SparseAccessorSubstitutesValues) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("SimpleSparseAccessor"));
  const Primitive& p = scene.meshes.at(0).primitives.at(0);
  EXPECT_EQ(p.triangleCount(), 12u);
  const auto has = [&](glm::vec3 v) { return std::find(p.positions.begin(), p.positions.end(), v) != p.positions.end(); };
  // Vertices 8, 10 and 12 of the base grid are replaced by the sparse values.
  for (glm::vec3 replaced : {glm::vec3(1, 1, 0), glm::vec3(3, 1, 0), glm::vec3(5, 1, 0)}) EXPECT_FALSE(has(replaced));
  for (glm::vec3 value : {glm::vec3(1, 2, 0), glm::vec3(3, 3, 0), glm::vec3(5, 4, 0)}) EXPECT_TRUE(has(value));
  EXPECT_EQ(p.bounds.max, glm::vec3(6, 4, 0));
}

TEST(GltfLoader, FlatNormalsWhenMissing) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("SimpleSparseAccessor"));
  const Primitive& p = scene.meshes.at(0).primitives.at(0);
  EXPECT_TRUE(hasWarningContaining(scene, "flat normals"));
  // De-indexed: every triangle has its own corners, all with its face normal.
  ASSERT_EQ(p.positions.size(), p.indices.size());
  for (size_t corner = 0; corner < p.indices.size(); corner += 3) {
    const glm::vec3 face = glm::normalize(
        glm::cross(p.positions[corner + 1] - p.positions[corner], p.positions[corner + 2] - p.positions[corner]));
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(glm::distance(p.normals[corner + k], face), 0.0f, 1e-6f);
  }
  EXPECT_EQ(p.normals.front(), glm::vec3(0, 0, 1));  // the sheet lies in z = 0, facing +Z
}

TEST(GltfLoader, NormalsFromFileAreKept) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("Box"));
  const Primitive& p = scene.meshes.at(0).primitives.at(0);
  EXPECT_EQ(p.positions.size(), 24u);  // still indexed: normals came from the file
  EXPECT_EQ(p.indices.size(), 36u);
  EXPECT_TRUE(p.uv0.empty());
  EXPECT_FALSE(hasWarningContaining(scene, "flat normals"));
}

TEST(GltfLoader, NodeHierarchyIsFlattened) {
  SG_REQUIRE_ASSETS();
  // Box: the root node's matrix turns Y-up into Z-up: world = root * child.
  const Scene scene = loadGltf(samplePath("Box"));
  ASSERT_EQ(scene.instances.size(), 1u);
  const glm::vec4 y = scene.instances[0].world * glm::vec4(0, 1, 0, 0);
  EXPECT_NEAR(glm::distance(glm::vec3(y), glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
  // SimpleMeshes: one mesh instanced by two nodes, the second translated by +1 x.
  const Scene meshes = loadGltf(samplePath("SimpleMeshes"));
  ASSERT_EQ(meshes.instances.size(), 2u);
  EXPECT_EQ(meshes.instances[0].mesh, meshes.instances[1].mesh);
  EXPECT_EQ(glm::vec3(meshes.instances[1].world[3]) - glm::vec3(meshes.instances[0].world[3]), glm::vec3(1, 0, 0));
}

TEST(GltfLoader, TextureTransformIsParsed) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("TextureTransformTest"), kGeometryOnly);
  const auto material = [&](std::string_view name) -> const Material& {
    const auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                                 [&](const Material& m) { return m.name == name; });
    EXPECT_NE(it, scene.materials.end()) << name;
    return *it;
  };
  EXPECT_EQ(material("Offset U").baseColorTexture.transform.offset, glm::vec2(0.5f, 0.0f));
  EXPECT_EQ(material("Offset UV").baseColorTexture.transform.offset, glm::vec2(0.5f, 0.5f));
  EXPECT_FLOAT_EQ(material("Rotation").baseColorTexture.transform.rotation, 0.39269908169872414f);
  EXPECT_EQ(material("Scale").baseColorTexture.transform.scale, glm::vec2(1.5f));
  const TextureTransform& all = material("All").baseColorTexture.transform;
  EXPECT_EQ(all.offset, glm::vec2(-0.2f, -0.1f));
  EXPECT_FLOAT_EQ(all.rotation, 0.3f);
  EXPECT_EQ(all.scale, glm::vec2(1.5f));
  EXPECT_TRUE(material("Correct").baseColorTexture.transform.isIdentity());

  // The extension's matrix: T * R * S. A quarter turn maps u to v (counter-clockwise).
  TextureTransform quarter;
  quarter.rotation = std::numbers::pi_v<float> / 2;
  quarter.offset = {0.0f, 1.0f};
  const glm::vec3 moved = quarter.matrix() * glm::vec3(1.0f, 0.0f, 1.0f);
  EXPECT_NEAR(moved.x, 0.0f, 1e-6f);
  EXPECT_NEAR(moved.y, 2.0f, 1e-6f);
  // Its sampler clamps and does not mipmap.
  const Texture& uv = scene.textures.at(static_cast<size_t>(material("Offset U").baseColorTexture.texture));
  const Sampler& sampler = scene.samplers.at(static_cast<size_t>(uv.sampler));
  EXPECT_EQ(sampler.wrapS, WrapMode::ClampToEdge);
  EXPECT_EQ(sampler.mipmapMode, MipmapMode::None);
}

TEST(GltfLoader, SamplersAndTextureNames) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("TextureSettingsTest"), kGeometryOnly);
  const auto byName = [&](std::string_view name) -> const Texture* {
    for (const Texture& texture : scene.textures)
      if (texture.name == name) return &texture;
    return nullptr;
  };
  const Texture* mirror = byName("TextureMirrorTextureT");
  ASSERT_NE(mirror, nullptr);
  const Sampler& s = scene.samplers.at(static_cast<size_t>(mirror->sampler));
  EXPECT_EQ(s.wrapS, WrapMode::Repeat);
  EXPECT_EQ(s.wrapT, WrapMode::MirroredRepeat);
  EXPECT_EQ(s.minFilter, Filter::Nearest);  // NEAREST_MIPMAP_LINEAR
  EXPECT_EQ(s.mipmapMode, MipmapMode::Linear);
  EXPECT_EQ(s.magFilter, Filter::Linear);
  const Texture* clamp = byName("TextureClampTextureT");
  ASSERT_NE(clamp, nullptr);
  EXPECT_EQ(scene.samplers.at(static_cast<size_t>(clamp->sampler)).wrapT, WrapMode::ClampToEdge);
}

TEST(GltfLoader, MaterialsAndColourSpaces) {
  SG_REQUIRE_ASSETS();
  const Scene helmet = loadGltf(samplePath("DamagedHelmet"), kGeometryOnly);
  ASSERT_EQ(helmet.materials.size(), 1u);
  const Material& m = helmet.materials[0];
  for (const TextureRef* ref : {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture,
                                &m.occlusionTexture, &m.emissiveTexture})
    ASSERT_TRUE(ref->present());
  EXPECT_TRUE(helmet.textures[static_cast<size_t>(m.baseColorTexture.texture)].srgb);
  EXPECT_TRUE(helmet.textures[static_cast<size_t>(m.emissiveTexture.texture)].srgb);
  EXPECT_FALSE(helmet.textures[static_cast<size_t>(m.normalTexture.texture)].srgb);
  EXPECT_FALSE(helmet.textures[static_cast<size_t>(m.metallicRoughnessTexture.texture)].srgb);
  EXPECT_EQ(helmet.textures[static_cast<size_t>(m.baseColorTexture.texture)].width, 2048u);
  EXPECT_TRUE(helmet.textures[static_cast<size_t>(m.baseColorTexture.texture)].pixels.empty());  // decodeImages = false

  const Scene alpha = loadGltf(samplePath("AlphaBlendModeTest"), kGeometryOnly);
  size_t opaque = 0, mask = 0, blend = 0;
  for (const Material& material : alpha.materials) {
    opaque += material.alphaMode == AlphaMode::Opaque;
    mask += material.alphaMode == AlphaMode::Mask;
    blend += material.alphaMode == AlphaMode::Blend;
  }
  EXPECT_GT(opaque, 0u);
  EXPECT_GT(mask, 0u);
  EXPECT_GT(blend, 0u);

  const Scene plane = loadGltf(samplePath("TwoSidedPlane"), kGeometryOnly);
  EXPECT_TRUE(plane.materials.at(0).doubleSided);

  const Scene multi = loadGltf(samplePath("MultiUVTest"), kGeometryOnly);
  EXPECT_EQ(multi.materials.at(0).emissiveTexture.texCoord, 1);
  EXPECT_FALSE(multi.meshes.at(0).primitives.at(0).uv1.empty());
}

TEST(GltfLoader, DecodedPixelsAreRgba) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("BoxTexturedNonPowerOfTwo"));
  ASSERT_EQ(scene.textures.size(), 1u);
  const Texture& texture = scene.textures[0];
  EXPECT_NE(texture.width & (texture.width - 1), 0u) << "a non-power-of-two width";
  EXPECT_EQ(texture.pixels.size(), size_t{texture.width} * texture.height * 4);
  EXPECT_EQ(texture.pixels[3], 255) << "opaque PNG gets alpha 255";
}

TEST(GltfLoader, VertexColours) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("VertexColorTest"), kGeometryOnly);
  bool found = false;
  for (const Mesh& mesh : scene.meshes)
    for (const Primitive& p : mesh.primitives)
      if (!p.colors.empty()) {
        found = true;
        for (const glm::vec4& c : p.colors) {
          EXPECT_GE(glm::min(glm::min(c.r, c.g), glm::min(c.b, c.a)), 0.0f);
          EXPECT_LE(glm::max(glm::max(c.r, c.g), glm::max(c.b, c.a)), 1.0f);
        }
      }
  EXPECT_TRUE(found);
}

TEST(GltfLoader, Cameras) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(samplePath("Cameras"));
  ASSERT_EQ(scene.cameras.size(), 2u);
  const Camera& perspective = scene.cameras[0];
  EXPECT_EQ(perspective.projection, Projection::Perspective);
  EXPECT_FLOAT_EQ(perspective.yfov, 0.7f);
  ASSERT_TRUE(perspective.aspectRatio.has_value());
  EXPECT_FLOAT_EQ(*perspective.aspectRatio, 1.0f);
  EXPECT_FLOAT_EQ(perspective.znear, 0.01f);
  ASSERT_TRUE(perspective.zfar.has_value());
  EXPECT_FLOAT_EQ(*perspective.zfar, 100.0f);
  EXPECT_EQ(perspective.position(), glm::vec3(0.5f, 0.5f, 3.0f));
  const Camera& orthographic = scene.cameras[1];
  EXPECT_EQ(orthographic.projection, Projection::Orthographic);
  EXPECT_FLOAT_EQ(orthographic.xmag, 1.0f);
  // view() takes the camera position to the origin.
  const glm::vec4 eye = perspective.view() * glm::vec4(perspective.position(), 1.0f);
  EXPECT_NEAR(glm::length(glm::vec3(eye)), 0.0f, 1e-6f);
}

TEST(GltfLoader, GlbAndGltfLoadAlike) {
  SG_REQUIRE_ASSIMP_MODELS();
  const Scene text = loadGltf(test::assimpDir() / "BoxTextured-glTF/BoxTextured.gltf");
  const Scene binary = loadGltf(test::assimpDir() / "BoxTextured-glTF-Binary/BoxTextured.glb");
  const Scene embedded = loadGltf(test::assimpDir() / "BoxTextured-glTF-Embedded/BoxTextured.gltf");
  for (const Scene* other : {&binary, &embedded}) {
    const Primitive& a = text.meshes.at(0).primitives.at(0);
    const Primitive& b = other->meshes.at(0).primitives.at(0);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.uv0, b.uv0);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(other->textures.size(), 1u);
    EXPECT_EQ(other->textures[0].pixels, text.textures.at(0).pixels);
  }
}

// glTF-Asset-Generator's Mesh_PrimitiveMode: one unit quad facing +Z drawn
// as a strip, a fan, or a list, indexed or not; points and lines are skipped.
TEST(GltfLoader, StripsAndFansBecomeLists) {
  SG_REQUIRE_ASSIMP_MODELS();
  const std::filesystem::path folder = test::assimpDir() / "glTF-Asset-Generator/Mesh_PrimitiveMode";
  for (const char* number : {"04", "05", "06", "11", "12", "13", "14", "15"}) {
    SCOPED_TRACE(number);
    const Scene scene = loadGltf(folder / ("Mesh_PrimitiveMode_" + std::string(number) + ".gltf"));
    const Primitive& p = scene.meshes.at(0).primitives.at(0);
    ASSERT_EQ(p.triangleCount(), 2u);
    float area = 0.0f;
    for (size_t corner = 0; corner < p.indices.size(); corner += 3) {
      const glm::vec3 a = p.positions[p.indices[corner]], b = p.positions[p.indices[corner + 1]],
                      c = p.positions[p.indices[corner + 2]];
      const glm::vec3 cross = glm::cross(b - a, c - a);
      EXPECT_GT(cross.z, 0.0f) << "counter-clockwise, facing the viewer";
      area += 0.5f * glm::length(cross);
    }
    EXPECT_NEAR(area, 1.0f, 1e-6f) << "the two triangles tile the quad";
  }
  for (const char* number : {"00", "01", "02", "03", "07", "08", "09", "10"}) {
    SCOPED_TRACE(number);
    const Scene scene = loadGltf(folder / ("Mesh_PrimitiveMode_" + std::string(number) + ".gltf"));
    EXPECT_TRUE(scene.meshes.at(0).primitives.empty());
    EXPECT_TRUE(hasWarningContaining(scene, "not rendered"));
  }
}

TEST(GltfLoader, LightsPunctual) {
  TempDir dir;
  const auto file = test::writeTriangleGltf(dir, "lights.gltf", R"(
    {"name": "sun", "rotation": [-0.70710678, 0, 0, 0.70710678], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"name": "bulb", "translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 1}}},
    {"name": "rig", "translation": [0, 5, 0], "children": [3]},
    {"name": "spot", "translation": [1, 0, 0], "extensions": {"KHR_lights_punctual": {"light": 2}}})",
                                            "0, 1, 2", R"(,
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"name": "sun", "type": "directional", "color": [1, 0.5, 0.25], "intensity": 3},
    {"type": "point", "intensity": 20, "range": 5, "extras": {"shadows": false}},
    {"type": "spot", "spot": {"innerConeAngle": 0.1, "outerConeAngle": 0.5}, "extras": {"shadows": true}}]}})");
  const Scene scene = loadGltf(file);
  ASSERT_EQ(scene.lights.size(), 3u);
  const Light& sun = scene.lights[0];
  EXPECT_EQ(sun.type, LightType::Directional);
  EXPECT_EQ(sun.name, "sun");
  EXPECT_EQ(sun.color, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(sun.intensity, 3.0f);
  EXPECT_NEAR(glm::distance(sun.direction, glm::vec3(0, -1, 0)), 0.0f, 1e-5f) << "-Z turned to point down";
  const Light& bulb = scene.lights[1];
  EXPECT_EQ(bulb.type, LightType::Point);
  EXPECT_EQ(bulb.position, glm::vec3(1, 2, 3));
  EXPECT_FLOAT_EQ(bulb.range, 5.0f);
  EXPECT_EQ(bulb.color, glm::vec3(1.0f));
  const Light& spot = scene.lights[2];
  EXPECT_EQ(spot.type, LightType::Spot);
  EXPECT_EQ(spot.position, glm::vec3(1, 5, 0)) << "placed by its parent too";
  EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.1f);
  EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.5f);
  EXPECT_EQ(spot.direction, glm::vec3(0, 0, -1));
  EXPECT_TRUE(sun.shadows) << "lights cast shadows unless their extras say otherwise";
  EXPECT_FALSE(bulb.shadows);
  EXPECT_TRUE(spot.shadows);
}

TEST(GltfLoader, LightShadowsExtraMustBeABoolean) {
  TempDir dir;
  const auto file = test::writeTriangleGltf(dir, "bad-shadows.gltf",
                                            R"({"name": "bulb", "extensions": {"KHR_lights_punctual": {"light": 0}}})",
                                            "0", R"(,
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "extras": {"shadows": "yes"}}]}})");
  try {
    loadGltf(file);
    FAIL() << "a non-boolean extras.shadows loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("extras.shadows must be true or false"), std::string::npos) << e.what();
  }
}

TEST(GltfLoader, EmissiveStrength) {
  TempDir dir;
  const auto material = [&](const std::string& name, const std::string& strength) {
    return test::writeTriangleGltf(dir, name, R"({"name": "t", "mesh": 0})", "0", R"(,
  "extensionsUsed": ["KHR_materials_emissive_strength"],
  "materials": [{"emissiveFactor": [1, 0.5, 0]},
                {"emissiveFactor": [1, 0.5, 0], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": )" +
                                                 strength + "}}}]");
  };
  const Scene scene = loadGltf(material("strength.gltf", "40"));
  ASSERT_GE(scene.materials.size(), 2u);  // then the default material of the unassigned primitive
  EXPECT_FLOAT_EQ(scene.materials[0].emissiveStrength, 1.0f) << "the default";
  EXPECT_FLOAT_EQ(scene.materials[1].emissiveStrength, 40.0f);
  EXPECT_EQ(scene.materials[1].emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f)) << "the factor stays as authored";
  try {
    loadGltf(material("negative.gltf", "-2"));
    FAIL() << "a negative emissiveStrength loaded";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("emissiveStrength must be a finite number >= 0"), std::string::npos)
        << e.what();
  }
}

TEST(GltfLoader, ShadingModeFromNodeExtras) {
  TempDir dir;
  const auto file = test::writeTriangleGltf(dir, "extras.gltf", R"(
    {"name": "decoupled", "mesh": 0, "extras": {"shading": "decoupled"}},
    {"name": "plain", "mesh": 0},
    {"name": "group", "extras": {"shading": "forward"}, "children": [3, 4]},
    {"name": "inherits", "mesh": 0},
    {"name": "overrides", "mesh": 0, "extras": {"shading": "auto"}},
    {"name": "typo", "mesh": 0, "extras": {"shading": "sometimes"}},
    {"name": "other extras", "mesh": 0, "extras": {"author": "me"}})",
                                            "0, 1, 2, 5, 6");
  const Scene scene = loadGltf(file);
  std::map<std::string, ShadingMode> modes;
  for (const Instance& instance : scene.instances) modes[instance.name] = instance.shading;
  EXPECT_EQ(modes.at("decoupled"), ShadingMode::Decoupled);
  EXPECT_EQ(modes.at("plain"), ShadingMode::Auto);
  EXPECT_EQ(modes.at("inherits"), ShadingMode::Forward);
  EXPECT_EQ(modes.at("overrides"), ShadingMode::Auto);
  EXPECT_EQ(modes.at("typo"), ShadingMode::Auto);
  EXPECT_EQ(modes.at("other extras"), ShadingMode::Auto);
  EXPECT_TRUE(hasWarningContaining(scene, "extras.shading"));
}

TEST(GltfLoader, DefaultMaterialAndSampler) {
  TempDir dir;
  const Scene scene = loadGltf(test::writeTriangleGltf(dir, "plain.gltf", R"({"mesh": 0})", "0"));
  ASSERT_EQ(scene.materials.size(), 1u);
  const Material& m = scene.materials[0];
  EXPECT_EQ(scene.meshes.at(0).primitives.at(0).material, 0);
  EXPECT_EQ(m.baseColorFactor, glm::vec4(1.0f));
  EXPECT_FLOAT_EQ(m.metallicFactor, 1.0f);
  EXPECT_FLOAT_EQ(m.roughnessFactor, 1.0f);
  EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
}

TEST(GltfLoader, ByteStrideIsHonoured) {
  TempDir dir;
  // POSITION and TEXCOORD_0 interleaved: x y z u v per vertex, 20-byte stride.
  dir.write("interleaved.bin", test::bytesOf(std::vector<float>{0, 0, 0, 0, 1,  //
                                                                1, 0, 0, 1, 1,  //
                                                                0, 1, 0, 0, 0}));
  const auto file = dir.write("interleaved.gltf", R"({
  "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}}]}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
    {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 3, "type": "VEC2"}],
  "bufferViews": [{"buffer": 0, "byteLength": 60, "byteStride": 20}],
  "buffers": [{"uri": "interleaved.bin", "byteLength": 60}]})");
  const Scene scene = loadGltf(file);
  const Primitive& p = scene.meshes.at(0).primitives.at(0);
  EXPECT_EQ(p.positions, (std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(p.uv0, (std::vector<glm::vec2>{{0, 1}, {1, 1}, {0, 0}}));
}

TEST(GltfLoader, NormalizedIntegerTexCoordsAndColours) {
  TempDir dir;
  // TEXCOORD_0 as normalized unsigned shorts, COLOR_0 as normalized unsigned bytes (vec3).
  dir.write("quantized.bin",
            test::concat({test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}),
                          test::bytesOf(std::vector<uint16_t>{0, 0, 65535, 0, 0, 65535}),
                          {255, 0, 0, 0, 0, 255, 0, 0, 0, 0, 255, 0}}));
  const auto file = dir.write("quantized.gltf", R"({
  "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1, "COLOR_0": 2}}]}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
    {"bufferView": 1, "componentType": 5123, "normalized": true, "count": 3, "type": "VEC2"},
    {"bufferView": 2, "componentType": 5121, "normalized": true, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12},
                  {"buffer": 0, "byteOffset": 48, "byteLength": 12, "byteStride": 4}],
  "buffers": [{"uri": "quantized.bin", "byteLength": 60}]})");
  const Scene scene = loadGltf(file);
  const Primitive& p = scene.meshes.at(0).primitives.at(0);
  EXPECT_EQ(p.uv0, (std::vector<glm::vec2>{{0, 0}, {1, 0}, {0, 1}}));
  EXPECT_EQ(p.colors, (std::vector<glm::vec4>{{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}}));
}

}  // namespace
}  // namespace sg::scene
