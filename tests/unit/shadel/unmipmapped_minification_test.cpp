// Auto mode's forward verdict for textures without mip levels: their texels per pixel.
#include <gtest/gtest.h>

#include <shadelgraph/shadel/unmipmapped_minification.hpp>

namespace sg::shadel {
namespace {

// A 2 x 2 quad in z = 0 whose TEXCOORD_0 spans [0,1]² (u = x / 2), with one
// material per texture slot configuration below.
scene::Scene quadScene(scene::MipmapMode mipmaps, uint32_t textureSize, float transformScale = 1.0f) {
  scene::Scene scene;
  scene.samplers = {scene::Sampler{.minFilter = scene::Filter::Linear, .mipmapMode = mipmaps}};
  scene.textures.resize(1);
  scene.textures[0].name = "uv";
  scene.textures[0].width = textureSize;
  scene.textures[0].height = textureSize / 2;  // the larger side counts
  scene.textures[0].sampler = 0;
  scene.materials.resize(1);
  scene.materials[0].baseColorTexture.texture = 0;
  scene.materials[0].baseColorTexture.transform.scale = glm::vec2(transformScale);
  scene::Primitive p;
  p.positions = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  p.normals.assign(4, {0, 0, 1});
  p.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = 0;
  scene::Mesh mesh;
  mesh.primitives.push_back(p);
  scene.meshes.push_back(mesh);
  return scene;
}

TEST(UnmipmappedMinification, TexelsPerObjectUnitOfTheTextureWithoutMips) {
  const scene::Scene scene = quadScene(scene::MipmapMode::None, 256);
  const UnmipmappedTexels texels = unmipmappedTexels(scene, scene.meshes[0]);
  EXPECT_NEAR(texels.texelsPerUnit, 128.0, 1e-6);  // 256 texels over 2 units
  EXPECT_EQ(texels.texture, "uv");
  // KHR_texture_transform's scale repeats the texture 1.5 times over the quad.
  EXPECT_NEAR(unmipmappedTexels(quadScene(scene::MipmapMode::None, 256, 1.5f), scene.meshes[0]).texelsPerUnit, 192.0,
              1e-6);
}

TEST(UnmipmappedMinification, MipmappedTexturesAreNotCounted) {
  const scene::Scene scene = quadScene(scene::MipmapMode::Linear, 256);
  EXPECT_EQ(unmipmappedTexels(scene, scene.meshes[0]).texelsPerUnit, 0.0);
  scene::Scene untextured = scene;
  untextured.materials[0].baseColorTexture.texture = -1;
  EXPECT_EQ(unmipmappedTexels(untextured, untextured.meshes[0]).texelsPerUnit, 0.0);
}

TEST(UnmipmappedMinification, TexelsPerPixelFollowDistanceAndScale) {
  const UnmipmappedTexels texels{.texelsPerUnit = 128.0, .texture = "uv"};
  // 100 pixels per unit at distance 1: 1.28 texels per pixel; at distance 2, 2.56.
  EXPECT_NEAR(unmipmappedTexelsPerPixel(texels, 1.0, 1.0, 100.0), 1.28, 1e-9);
  EXPECT_NEAR(unmipmappedTexelsPerPixel(texels, 1.0, 2.0, 100.0), 2.56, 1e-9);
  EXPECT_GT(unmipmappedTexelsPerPixel(texels, 1.0, 2.0, 100.0), kMaxUnmipmappedTexelsPerPixel);
  EXPECT_LT(unmipmappedTexelsPerPixel(texels, 1.0, 1.0, 100.0), kMaxUnmipmappedTexelsPerPixel);
  // The object scaled 2x in the world: its texels twice as large.
  EXPECT_NEAR(unmipmappedTexelsPerPixel(texels, 2.0, 2.0, 100.0), 1.28, 1e-9);
  EXPECT_EQ(unmipmappedTexelsPerPixel({}, 1.0, 2.0, 100.0), 0.0);
  EXPECT_EQ(unmipmappedTexelsPerPixel(texels, 1.0, 2.0, 0.0), 0.0);  // no view
}

}  // namespace
}  // namespace sg::shadel
