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

TEST_F(MaterialVariants, EveryBuiltinLayerCompilesDecoupled) {
  for (const auto& name : registry_.materialNames()) {
    const auto& material = registry_.material(name);
    if (!registry_.runsIn(material, plugin::ShadingPath::Decoupled)) continue;
    for (const auto& layer : material.layers) {
      SCOPED_TRACE(layer);
      EXPECT_FALSE(compiler_.compile(passes::decoupledLayerVariant(registry_.layer(layer))).empty());
    }
  }
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
  const auto blur = passes::decoupledLayerVariant(registry_.layer("blur-v")).source;
  EXPECT_NE(blur.find("sgLayerImage_blur_u"), std::string::npos);
  EXPECT_EQ(blur.find("sgLayerImage_gltf_pbr"), std::string::npos) << "blur-v reads only blur-u";
  EXPECT_EQ(blur.find("sgLayerHistory"), std::string::npos) << "not persistent";
  const auto marble = passes::decoupledLayerVariant(registry_.layer("marble")).source;
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
    const auto request = decoupled ? passes::decoupledLayerVariant(registry_.layer("broken"))
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
