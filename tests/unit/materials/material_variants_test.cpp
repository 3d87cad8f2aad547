// The generated variants, compiled with glslang (no device): every built-in
// layer's decoupled variant and every built-in material's forward variant
// compile, the forward variant runs the whole stack, and an error in an
// author's layer is reported at the author's file and line.
#include <gtest/gtest.h>

#include <builtin_materials.hpp>
#include <builtin_shaders.hpp>
#include <shadelgraph/gpu/shader_compiler.hpp>
#include <forward/material_variant.hpp>
#include <layer-shade/layer_variant.hpp>
#include <shadelgraph/render/material_variants.hpp>

namespace sg {
namespace {

class MaterialVariants : public ::testing::Test {
 protected:
  MaterialVariants() {
    library_.add(gpu::builtinShaders());
    materials::registerBuiltinMaterials(registry_);
  }
  gpu::ShaderLibrary library_;
  gpu::ShaderCompiler compiler_{library_, {}};  // no disk cache
  plugin::Registry registry_;
};

// In every workgroup shape: lavapipe's 8 lanes (8 rows per invocation) to a 64-lane GPU wave (1).
TEST_F(MaterialVariants, EveryBuiltinLayerCompilesDecoupled) {
  for (const auto& name : registry_.materialNames()) {
    const auto& material = registry_.material(name);
    if (!registry_.runsIn(material, plugin::ShadingPath::Decoupled)) continue;
    for (const auto& layer : material.layers)
      for (const uint32_t rows : {1u, 2u, 4u, 8u}) {
        SCOPED_TRACE(layer + " rows " + std::to_string(rows));
        EXPECT_FALSE(compiler_.compile(passes::decoupledLayerVariant(registry_.layer(layer), rows)).empty());
      }
  }
}

TEST_F(MaterialVariants, ALayerShadeWorkgroupIsOneSubgroup) {
  EXPECT_EQ(passes::chunkRowsPerInvocation(8), 8u);   // lavapipe, 256-bit vectors
  EXPECT_EQ(passes::chunkRowsPerInvocation(16), 4u);
  EXPECT_EQ(passes::chunkRowsPerInvocation(32), 2u);  // NVIDIA, AMD wave32
  EXPECT_EQ(passes::chunkRowsPerInvocation(64), 1u);  // AMD wave64
  EXPECT_EQ(passes::chunkRowsPerInvocation(4), 8u);   // never fewer lanes than a chunk row
  EXPECT_EQ(passes::chunkRowsPerInvocation(128), 1u);
  const auto source = passes::decoupledLayerVariant(registry_.layer("gltf-pbr"), 2).source;
  EXPECT_NE(source.find("#define SG_CHUNK_ROWS_PER_INVOCATION 2u"), std::string::npos) << source;
  EXPECT_THROW(passes::decoupledLayerVariant(registry_.layer("gltf-pbr"), 3), std::invalid_argument);
  EXPECT_THROW(passes::decoupledLayerVariant(registry_.layer("gltf-pbr"), 16), std::invalid_argument);
}

TEST_F(MaterialVariants, EveryBuiltinMaterialCompilesForward) {
  for (const auto& name : registry_.materialNames()) {
    SCOPED_TRACE(name);
    const auto& material = registry_.materialFor(name, plugin::ShadingPath::Forward);
    EXPECT_FALSE(compiler_.compile(passes::forwardMaterialVariant(registry_, material)).empty());
  }
}

TEST_F(MaterialVariants, ForwardVariantRunsTheStackInOrder) {
  const auto source = passes::forwardMaterialVariant(registry_, registry_.material("bumps-forward")).source;
  const auto height = source.find("sgLayerValue_height = bumpHeight(s);");
  const auto normal = source.find("sgLayerValue_normal_from_height_screen = normalFromHeightScreen(s);");
  ASSERT_NE(height, std::string::npos) << source;
  ASSERT_NE(normal, std::string::npos) << source;
  EXPECT_LT(height, normal);
  EXPECT_NE(source.find("sgWriteForward(sgLayerValue_normal_from_height_screen)"), std::string::npos);
}

TEST_F(MaterialVariants, DecoupledVariantBindsOnlyWhatTheLayerDeclares) {
  const auto blur = passes::decoupledLayerVariant(registry_.layer("blur-v"), 8).source;
  EXPECT_NE(blur.find("sgLayerImage_blur_u"), std::string::npos);
  EXPECT_EQ(blur.find("sgLayerImage_gltf_pbr"), std::string::npos) << "blur-v reads only blur-u";
  EXPECT_EQ(blur.find("sgLayerHistory"), std::string::npos) << "not persistent";
  const auto marble = passes::decoupledLayerVariant(registry_.layer("marble"), 8).source;
  EXPECT_NE(marble.find("sgLayerHistory"), std::string::npos);
  EXPECT_NE(marble.find("layerReused"), std::string::npos);
}

TEST_F(MaterialVariants, AuthorErrorsPointIntoTheAuthorsFile) {
  library_.add("my-plugin/broken.glsl",
               "// a layer with a typo\n"
               "vec4 broken(Surface s) {\n"
               "  vec3 c = s.normal * 0.5 + 0.5;\n"
               "  return vec4(c, undefinedThing);\n"
               "}\n");
  registry_.beginPlugin("my-plugin");
  registry_.addLayer({.name = "broken", .source = "my-plugin/broken.glsl", .function = "broken"});
  registry_.addMaterial({.name = "broken", .layers = {"broken"}});
  for (const bool decoupled : {true, false}) {
    const auto request = decoupled ? passes::decoupledLayerVariant(registry_.layer("broken"), 8)
                                   : passes::forwardMaterialVariant(registry_, registry_.material("broken"));
    try {
      compiler_.compile(request);
      FAIL() << "compiled";
    } catch (const gpu::ShaderCompileError& e) {
      EXPECT_EQ(e.file(), "my-plugin/broken.glsl");
      EXPECT_EQ(e.line(), 4);
      const std::string message = render::layerCompileError(e, library_, "material layer 'broken'", "my-plugin").what();
      EXPECT_NE(message.find("material layer 'broken' (plugin 'my-plugin')"), std::string::npos) << message;
      EXPECT_NE(message.find("my-plugin/broken.glsl:4: "), std::string::npos) << message;
      EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace sg
