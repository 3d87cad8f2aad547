// The procedural primitives of the default scene: consistent winding,
// tangent handedness that matches the UV chart, and UVs inside [0,1]^2.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>
#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/scene/tangents.hpp>

namespace sg::scene {
namespace {

struct Named {
  const char* name;
  Primitive primitive;
};

std::vector<Named> allPrimitives() {
  return {{"box", makeBox({2, 1, 0.5f})},
          {"plane", makePlane(4, 3, 4)},
          {"cylinder", makeCylinder(0.5f, 2, 12)},
          {"sphere", makeSphere(1, 16, 8)},
          {"torus", makeTorus(1, 0.3f, 16, 8)}};
}

TEST(ProceduralMeshes, WindingFacesAlongVertexNormals) {
  for (const auto& [name, p] : allPrimitives()) {
    int wrong = 0;
    for (size_t t = 0; t < p.indices.size(); t += 3) {
      const uint32_t a = p.indices[t], b = p.indices[t + 1], c = p.indices[t + 2];
      const glm::vec3 face = glm::cross(p.positions[b] - p.positions[a], p.positions[c] - p.positions[a]);
      if (glm::length(face) < 1e-9f) continue;
      const glm::vec3 n = p.normals[a] + p.normals[b] + p.normals[c];
      if (glm::dot(face, n) <= 0) ++wrong;
    }
    EXPECT_EQ(wrong, 0) << name << ": triangles wound against their normals";
  }
}

TEST(ProceduralMeshes, TangentHandednessMatchesUvChart) {
  for (const auto& [name, p] : allPrimitives()) {
    int wrong = 0, checked = 0;
    for (size_t t = 0; t < p.indices.size(); t += 3) {
      const uint32_t i[3] = {p.indices[t], p.indices[t + 1], p.indices[t + 2]};
      const glm::vec3 e1 = p.positions[i[1]] - p.positions[i[0]], e2 = p.positions[i[2]] - p.positions[i[0]];
      const glm::vec2 d1 = p.uv0[i[1]] - p.uv0[i[0]], d2 = p.uv0[i[2]] - p.uv0[i[0]];
      const float det = d1.x * d2.y - d2.x * d1.y;
      if (std::abs(det) < 1e-12f) continue;
      // dP/du and dP/dv of this triangle.
      const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det, dPdv = (e2 * d1.x - e1 * d2.x) / det;
      for (uint32_t v : i) {
        const glm::vec3 n = p.normals[v], tangent = glm::vec3(p.tangents[v]);
        const glm::vec3 bitangent = glm::cross(n, tangent) * p.tangents[v].w;
        ++checked;
        // glTF: the bitangent is the image's up, against +V (V grows downwards).
        if (glm::dot(tangent, dPdu) <= 0 || glm::dot(bitangent, dPdv) >= 0) ++wrong;
      }
    }
    EXPECT_GT(checked, 0) << name;
    EXPECT_EQ(wrong, 0) << name << ": tangent frame disagrees with the UV gradients";
  }
}

// The analytic tangents agree with the loader's generated ones (tangents.hpp)
// on handedness everywhere and on direction nearly everywhere.
TEST(ProceduralMeshes, TangentsAgreeWithGeneratedOnes) {
  for (const auto& [name, p] : allPrimitives()) {
    const std::vector<glm::vec4> generated = cornerTangents(p.positions, p.normals, p.uv0, p.indices);
    size_t sameHandedness = 0, sameDirection = 0;
    for (size_t c = 0; c < generated.size(); ++c) {
      const glm::vec4 analytic = p.tangents[p.indices[c]];
      sameHandedness += generated[c].w == analytic.w;
      sameDirection += glm::dot(glm::vec3(generated[c]), glm::vec3(analytic)) > 0.9f;
    }
    EXPECT_EQ(sameHandedness, generated.size()) << name;
    EXPECT_GE(sameDirection, generated.size() * 9 / 10) << name;
  }
}

TEST(ProceduralMeshes, UvsInsideUnitSquare) {
  for (const auto& [name, p] : allPrimitives()) {
    ASSERT_EQ(p.uv0.size(), p.positions.size()) << name;
    for (const auto& uv : p.uv0) {
      EXPECT_GE(uv.x, 0.0f) << name;
      EXPECT_LE(uv.x, 1.0f) << name;
      EXPECT_GE(uv.y, 0.0f) << name;
      EXPECT_LE(uv.y, 1.0f) << name;
    }
  }
}

TEST(DefaultScene, EveryMeshHasAUniqueChart) {
  const Scene s = makeDefaultScene(16);
  for (const auto& mesh : s.meshes) {
    const auto verdict = chooseShadingChart(mesh);
    EXPECT_TRUE(verdict.unique) << mesh.name << ": " << verdict.reason;
  }
}

TEST(DefaultScene, HasLightsCameraAndTexturedMaterials) {
  const Scene s = makeDefaultScene(64);
  EXPECT_GE(s.lights.size(), 2u);
  EXPECT_LE(s.lights.size(), 4u);
  EXPECT_EQ(s.cameras.size(), 1u);
  EXPECT_GE(s.instances.size(), 8u);
  bool glossyNormalMapped = false;
  for (const auto& m : s.materials)
    glossyNormalMapped |= m.roughnessFactor < 0.3f && m.normalTexture.present();
  EXPECT_TRUE(glossyNormalMapped) << "the shimmer case needs a glossy normal-mapped material";
  for (const auto& t : s.textures) EXPECT_EQ(t.pixels.size(), size_t(t.width) * t.height * 4) << t.name;
}

}  // namespace
}  // namespace sg::scene
