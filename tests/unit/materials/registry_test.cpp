// The registry's consistency rules, over the built-ins and hand-made broken ones.
#include <gtest/gtest.h>

#include <algorithm>

#include <builtin_materials.hpp>
#include <shadelgraph/plugin/registry.hpp>

namespace sg {
namespace {

using plugin::LayerPaths;
using plugin::Registry;

bool mentions(const std::vector<std::string>& problems, const std::string& a, const std::string& b) {
  return std::any_of(problems.begin(), problems.end(), [&](const std::string& p) {
    return p.find(a) != std::string::npos && p.find(b) != std::string::npos;
  });
}

Registry withLayer(plugin::MaterialLayer layer) {
  Registry r;
  r.beginPlugin("test-plugin");
  r.addLayer({.name = "base", .source = "base.glsl", .function = "base"});
  r.addLayer(std::move(layer));
  return r;
}

TEST(Registry, BuiltinsAreConsistent) {
  Registry r;
  materials::registerBuiltinMaterials(r);
  EXPECT_EQ(r.problems(), std::vector<std::string>{});
  for (const char* name : {"gltf-pbr", "bumps", "skin", "marble", "debug-uv-checker", "debug-detail-level",
                           "debug-triangle-id"})
    EXPECT_TRUE(r.hasMaterial(name)) << name;
  EXPECT_EQ(r.material("skin").layers.size(), 3u);
}

TEST(Registry, DuplicateNamesNameBothPlugins) {
  Registry r;
  materials::registerBuiltinMaterials(r);
  r.beginPlugin("late");
  try {
    r.addLayer({.name = "height", .source = "x.glsl", .function = "f"});
    FAIL() << "duplicate accepted";
  } catch (const plugin::PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("'height' (plugin 'late')"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("plugin 'built-in'"), std::string::npos) << e.what();
  }
}

TEST(Registry, RejectsBadNamesAndEmptyDeclarations) {
  Registry r;
  EXPECT_THROW(r.addLayer({.name = "9lives", .source = "a.glsl", .function = "f"}), plugin::PluginError);
  EXPECT_THROW(r.addLayer({.name = "has space", .source = "a.glsl", .function = "f"}), plugin::PluginError);
  EXPECT_THROW(r.addLayer({.name = "nosource", .function = "f"}), plugin::PluginError);
  EXPECT_THROW(r.addMaterial({.name = ""}), plugin::PluginError);
}

TEST(Registry, NeighbourhoodReadMustBeDecoupledOnly) {
  Registry r = withLayer({.name = "blur", .source = "b.glsl", .function = "b", .reads = {{"base", 1}}});
  r.addMaterial({.name = "m", .layers = {"base", "blur"}});
  EXPECT_TRUE(mentions(r.problems(), "'blur' (plugin 'test-plugin')", "DecoupledOnly"));
}

TEST(Registry, RadiusIsBounded) {
  Registry r = withLayer({.name = "wide", .source = "b.glsl", .function = "b", .reads = {{"base", 9}},
                          .paths = LayerPaths::DecoupledOnly});
  EXPECT_TRUE(mentions(r.problems(), "'wide'", "radius 9"));
}

TEST(Registry, ChainedRadiiAreBounded) {
  Registry r = withLayer({.name = "a", .source = "b.glsl", .function = "b", .reads = {{"base", 5}},
                          .paths = LayerPaths::DecoupledOnly});
  r.addLayer({.name = "b", .source = "b.glsl", .function = "b", .reads = {{"a", 5}}, .paths = LayerPaths::DecoupledOnly});
  r.addMaterial({.name = "m", .layers = {"base", "a", "b"}, .forwardFallback = "f"});
  r.addMaterial({.name = "f", .layers = {"base"}});
  EXPECT_TRUE(mentions(r.problems(), "material 'm'", "add up to 10"));
}

TEST(Registry, ReadsMustComeEarlierInTheStack) {
  Registry r = withLayer({.name = "late", .source = "b.glsl", .function = "b", .reads = {{"base", 0}}});
  r.addMaterial({.name = "backwards", .layers = {"late", "base"}});
  EXPECT_TRUE(mentions(r.problems(), "material 'backwards'", "does not come before it"));
}

TEST(Registry, UnknownLayerInStack) {
  Registry r;
  r.addMaterial({.name = "m", .layers = {"nothing"}});
  EXPECT_TRUE(mentions(r.problems(), "material 'm'", "'nothing' is not registered"));
}

TEST(Registry, DecoupledOnlyNeedsAForwardFallbackThatRunsForward) {
  Registry r = withLayer({.name = "n", .source = "b.glsl", .function = "b", .reads = {{"base", 1}},
                          .paths = LayerPaths::DecoupledOnly});
  r.addMaterial({.name = "none", .layers = {"base", "n"}});
  r.addMaterial({.name = "self", .layers = {"base", "n"}, .forwardFallback = "none"});
  r.addMaterial({.name = "missing", .layers = {"base", "n"}, .forwardFallback = "ghost"});
  const auto problems = r.problems();
  EXPECT_TRUE(mentions(problems, "material 'none'", "names no forward fallback"));
  EXPECT_TRUE(mentions(problems, "material 'self'", "cannot run forward either"));
  EXPECT_TRUE(mentions(problems, "material 'missing'", "'ghost' is not registered"));
  EXPECT_THROW(r.check(), plugin::PluginError);
}

TEST(Registry, LastLayerWritesTheShadedColour) {
  Registry r = withLayer({.name = "h", .source = "b.glsl", .function = "b", .format = graph::Format::R16F});
  r.addLayer({.name = "p", .source = "b.glsl", .function = "b", .persistent = true});
  r.addMaterial({.name = "narrow", .layers = {"h"}});
  r.addMaterial({.name = "cached", .layers = {"p"}});
  EXPECT_TRUE(mentions(r.problems(), "material 'narrow'", "must be RGBA16F"));
  EXPECT_TRUE(mentions(r.problems(), "material 'cached'", "is persistent"));
}

TEST(Registry, MaterialForPicksTheForwardFallback) {
  Registry r;
  materials::registerBuiltinMaterials(r);
  EXPECT_EQ(r.materialFor("bumps", plugin::ShadingPath::Decoupled).name, "bumps");
  EXPECT_EQ(r.materialFor("bumps", plugin::ShadingPath::Forward).name, "bumps-forward");
  EXPECT_EQ(r.materialFor("gltf-pbr", plugin::ShadingPath::Forward).name, "gltf-pbr");
  EXPECT_FALSE(r.runsIn(r.material("bumps-forward"), plugin::ShadingPath::Decoupled));
  try {
    (void)r.material("nope");
    FAIL();
  } catch (const plugin::PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("known: "), std::string::npos);
  }
}

}  // namespace
}  // namespace sg
