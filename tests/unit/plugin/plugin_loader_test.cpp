// loadPlugin / loadPluginDirectory / $SG_PLUGIN_PATH against real shared
// libraries (tests/plugins): the good module's registrations and the one-line
// message of every way a library can fail to be a plugin.
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/plugin/plugin_api.hpp>
#include <shadelgraph/plugin/plugin_loader.hpp>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "test_support.hpp"

namespace sg::plugin {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

// The PluginError message of `load`, or a failure when it does not throw one.
std::string errorOf(const std::function<void()>& load) {
  try {
    load();
  } catch (const PluginError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no PluginError";
  return {};
}

// A copy under a new name (a copy is a different file, so dlopen loads it
// again: registrations go to the registry passed this time).
fs::path copyTo(const fs::path& library, const fs::path& directory, const std::string& name) {
  fs::copy_file(library, directory / name);
  return directory / name;
}

// Sets an environment variable for one test.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) { setenv(name, value.c_str(), 1); }
  ~ScopedEnv() { unsetenv(name_); }

 private:
  const char* name_;
};

TEST(PluginLoader, GoodPluginRegistersItsLayerMaterialAndPass) {
  Registry registry;
  const LoadedPlugin loaded = loadPlugin(SG_PLUGIN_GOOD, registry);
  EXPECT_EQ(loaded.name, "test-good");
  ASSERT_TRUE(registry.hasLayer("test-layer"));
  ASSERT_TRUE(registry.hasMaterial("test-material"));
  EXPECT_EQ(registry.layer("test-layer").plugin, "test-good");
  EXPECT_EQ(registry.material("test-material").layers, std::vector<std::string>{"test-layer"});
  EXPECT_TRUE(registry.problems().empty());
  // The plugin got its own directory, for its GLSL.
  ASSERT_EQ(registry.shaderDirectories().size(), 1u);
  EXPECT_EQ(registry.shaderDirectories()[0], fs::absolute(SG_PLUGIN_GOOD).parent_path() / "shaders");
  // What the host registers afterwards is the host's again.
  EXPECT_EQ(registry.currentPlugin(), "built-in");
}

TEST(PluginLoader, PluginPassAndFrameAreRegisteredUnderThePluginsName) {
  Registry registry;
  loadPlugin(SG_PLUGIN_GOOD, registry);
  ASSERT_TRUE(registry.hasPass("test-post"));
  EXPECT_EQ(registry.pass("test-post").plugin, "test-good");
  EXPECT_EQ(registry.pass("test-post").reads, std::vector<std::string>{"scene.hdr"});
  ASSERT_TRUE(registry.hasFrame("test-frame"));
  EXPECT_EQ(registry.frame("test-frame").base, "decoupled");
}

TEST(PluginLoader, MissingFileIsNamed) {
  Registry registry;
  EXPECT_THAT(errorOf([&] { loadPlugin("/nonexistent/libnothing.so", registry); }),
              AllOf(HasSubstr("/nonexistent/libnothing.so"), HasSubstr("no such file")));
}

TEST(PluginLoader, NotALibraryReportsDlerror) {
  test::TempDir dir;
  // Longer than an ELF header, so dlopen reads it and says what is wrong.
  const fs::path fake = dir.write("libfake.so", std::string(256, '#'));
  Registry registry;
  EXPECT_THAT(errorOf([&] { loadPlugin(fake, registry); }),
              AllOf(HasSubstr("libfake.so"), HasSubstr("cannot be loaded"), HasSubstr("invalid ELF header")));
}

TEST(PluginLoader, LibraryWithoutEntryPointIsNotAPlugin) {
  Registry registry;
  EXPECT_THAT(errorOf([&] { loadPlugin(SG_PLUGIN_NO_ENTRY, registry); }),
              AllOf(HasSubstr(fs::path(SG_PLUGIN_NO_ENTRY).filename().string()),
                    HasSubstr("is not a shadelgraph plugin: it exports no sg_plugin_info")));
}

TEST(PluginLoader, WrongAbiVersionIsRefused) {
  Registry registry;
  EXPECT_THAT(errorOf([&] { loadPlugin(SG_PLUGIN_WRONG_ABI, registry); }),
              AllOf(HasSubstr(fs::path(SG_PLUGIN_WRONG_ABI).filename().string()),
                    HasSubstr("was built for plugin ABI 999, this shadelgraph has " +
                              std::to_string(SG_PLUGIN_ABI_VERSION) + ": rebuild it against this version")));
}

TEST(PluginLoader, ThrowingRegisterFunctionIsNamed) {
  Registry registry;
  EXPECT_THAT(errorOf([&] { loadPlugin(SG_PLUGIN_THROWS, registry); }),
              AllOf(HasSubstr("plugin 'test-throws'"), HasSubstr("cannot find its lookup table")));
  EXPECT_EQ(registry.currentPlugin(), "built-in");
}

TEST(PluginLoader, DirectoryLoadsEverySharedLibraryInNameOrder) {
  test::TempDir dir;
  copyTo(SG_PLUGIN_GOOD, dir.path(), "a-good.so");
  copyTo(SG_PLUGIN_WRONG_ABI, dir.path(), "b-wrong-abi.so");
  dir.write("README.txt", "not a plugin, not loaded");
  Registry registry;
  // a-good loads first (its layer is there), then b-wrong-abi stops the load.
  EXPECT_THAT(errorOf([&] { loadPluginDirectory(dir.path(), registry); }), HasSubstr("b-wrong-abi.so"));
  EXPECT_TRUE(registry.hasLayer("test-layer"));
}

TEST(PluginLoader, DirectoryOfGoodPlugins) {
  test::TempDir dir;
  copyTo(SG_PLUGIN_GOOD, dir.path(), "libgood.so");
  Registry registry;
  const auto loaded = loadPluginDirectory(dir.path(), registry);
  ASSERT_EQ(loaded.size(), 1u);
  EXPECT_EQ(loaded[0].library, dir.path() / "libgood.so");
  EXPECT_TRUE(registry.hasMaterial("test-material"));
}

TEST(PluginLoader, MissingDirectoryIsNamed) {
  Registry registry;
  EXPECT_THAT(errorOf([&] { loadPluginDirectory("/nonexistent/plugins", registry); }),
              AllOf(HasSubstr("/nonexistent/plugins"), HasSubstr("no such directory")));
}

TEST(PluginLoader, PluginPathIsColonSeparated) {
  ScopedEnv env("SG_PLUGIN_PATH", "/a::/b/c:");
  EXPECT_EQ(pluginPathDirectories(), (std::vector<fs::path>{"/a", "/b/c"}));
}

TEST(PluginLoader, LoadPluginsTakesPluginPathThenArguments) {
  test::TempDir dir;
  fs::create_directory(dir.path() / "env");
  copyTo(SG_PLUGIN_GOOD, dir.path() / "env", "libgood.so");
  ScopedEnv env("SG_PLUGIN_PATH", (dir.path() / "env").string());
  Registry registry;
  // The same plugin again from the command line: its layer is already registered.
  EXPECT_THAT(errorOf([&] { loadPlugins({copyTo(SG_PLUGIN_GOOD, dir.path(), "libagain.so")}, registry); }),
              AllOf(HasSubstr("plugin 'test-good'"), HasSubstr("already registered")));
  EXPECT_TRUE(registry.hasLayer("test-layer"));
}

TEST(PluginLoader, PluginPathNamingNoDirectoryIsAnError) {
  ScopedEnv env("SG_PLUGIN_PATH", "/nonexistent/sg-plugins");
  Registry registry;
  EXPECT_THAT(errorOf([&] { loadPlugins({}, registry); }),
              AllOf(HasSubstr("$SG_PLUGIN_PATH"), HasSubstr("/nonexistent/sg-plugins")));
}

}  // namespace
}  // namespace sg::plugin
