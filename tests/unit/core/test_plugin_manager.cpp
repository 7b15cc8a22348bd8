// PluginManager: lazy loading, the ABI rule, name checks and error sentences.
// Uses the test-only plugins of tests/plugins (FEMTO_TEST_PLUGIN_DIR).
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>

#include <femto/base/error.h>
#include <femto/core/plugin.h>
#include <femto/core/spelling.h>

#include "../../plugins/test_object.h"
#include "plugin_util.h"

namespace femto {
namespace {

const std::filesystem::path TestPluginDir = FEMTO_TEST_PLUGIN_DIR;

PluginManager& manager() {
  static bool prepared = [] {
    PluginManager::instance().prependSearchPath(TestPluginDir);
    return true;
  }();
  (void)prepared;
  return PluginManager::instance();
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(PluginManager, LoadsOnlyWhatIsNamed) {
  PluginManager& pm = manager();
  std::vector<std::string> before = pm.loadedPlugins();
  ASSERT_FALSE(contains(before, "test_good"));
  // Several plugins sit in the test directory; naming one must load only it.
  Properties props("test_good");
  props.setFloat("value", 2.5);
  ObjectRef object = pm.create(ObjectKind::Texture, props);
  auto* texture = dynamic_cast<test::TestTexture*>(object.get());
  ASSERT_NE(texture, nullptr);
  EXPECT_FLOAT_EQ(texture->value(), 2.5f);

  std::vector<std::string> after = pm.loadedPlugins();
  std::vector<std::string> expected = before;
  expected.push_back("test_good");
  EXPECT_EQ(after, expected);
  // A second create reuses the library.
  pm.create(ObjectKind::Texture, Properties("test_good"));
  EXPECT_EQ(pm.loadedPlugins(), expected);
}

TEST(PluginManager, NothingLoadedAtStartup) {
  // Each ctest case runs in a fresh process (gtest_discover_tests), where no
  // plugin may be loaded before one is named. Run alone, this checks that.
  if (::testing::UnitTest::GetInstance()->test_to_run_count() > 1) GTEST_SKIP() << "only meaningful in a fresh process";
  EXPECT_TRUE(manager().loadedPlugins().empty());
}

TEST(PluginManager, RefusesOtherAbiByName) {
  std::string message = test::errorMessageOf([] { manager().load("test_wrong_abi"); });
  std::string file = (TestPluginDir / "test_wrong_abi.so").string();
  EXPECT_EQ(message, "plugin \"test_wrong_abi\" (" + file + ") was built for femto plugin ABI " +
                         std::to_string(FemtoAbiVersion + 1) + ", this femto has ABI " +
                         std::to_string(FemtoAbiVersion) + ": rebuild it");
  EXPECT_FALSE(contains(manager().loadedPlugins(), "test_wrong_abi"));
  // Same rule through an explicit file.
  EXPECT_NE(test::errorMessageOf([&] { manager().loadFile(file); }).find("was built for femto plugin ABI"), std::string::npos);
}

TEST(PluginManager, MissingPluginNamesSearchPathAndCloseMatches) {
  std::string message = test::errorMessageOf([] { manager().load("test_goood"); });
  EXPECT_NE(message.find("plugin \"test_goood\" not found"), std::string::npos) << message;
  for (const auto& dir : manager().searchPath()) EXPECT_NE(message.find(dir.string()), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean \"test_good\""), std::string::npos) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 0) << "one sentence";
}

TEST(PluginManager, RefusesInvalidNames) {
  for (std::string name : {"", "../test_good", "dir/test_good", "test_good.so", "/tmp/x", "has space", "semi;colon"}) {
    std::string message = test::errorMessageOf([&] { manager().load(name); });
    EXPECT_NE(message.find("invalid plugin name \"" + name + "\""), std::string::npos) << message;
    EXPECT_FALSE(PluginManager::validName(name)) << name;
  }
  EXPECT_TRUE(PluginManager::validName("rough-conductor_2"));
}

TEST(PluginManager, DescriptorNameMustMatchFileName) {
  std::string message = test::errorMessageOf([] { manager().load("test_misnamed"); });
  EXPECT_NE(message.find("plugin \"test_misnamed\""), std::string::npos) << message;
  EXPECT_NE(message.find("declares the name \"something_else\""), std::string::npos) << message;
}

TEST(PluginManager, LibraryWithoutEntryPointIsNotAPlugin) {
  std::string message = test::errorMessageOf([] { manager().load("test_no_entry"); });
  EXPECT_NE(message.find("is not a femto plugin"), std::string::npos) << message;
  EXPECT_NE(message.find(PluginEntryPoint), std::string::npos) << message;
}

TEST(PluginManager, KindMismatchNamesBothKinds) {
  Properties props("test_good");
  props.setLocation({"scene.xml", 7});
  std::string message = test::errorMessageOf([&] { manager().create(ObjectKind::BSDF, props); });
  EXPECT_EQ(message, "scene.xml:7: plugin \"test_good\" creates a <texture>, but it is used here as a <bsdf>");
}

TEST(PluginManager, ConcurrentLoadsShareOneLibrary) {
  PluginManager& pm = manager();
  std::vector<const PluginDescriptor*> seen(8);
  std::vector<std::thread> threads;
  for (size_t i = 0; i < seen.size(); ++i) threads.emplace_back([&, i] { seen[i] = &pm.load("test_good"); });
  for (auto& t : threads) t.join();
  for (auto* d : seen) EXPECT_EQ(d, seen[0]);
  auto loaded = pm.loadedPlugins();
  EXPECT_EQ(std::count(loaded.begin(), loaded.end(), "test_good"), 1);
}

TEST(PluginManager, DiscoverAllSkipsBrokenLibraries) {
  std::vector<std::string> names;
  for (const PluginDescriptor* d : manager().discoverAll()) names.push_back(d->name);
  EXPECT_TRUE(contains(names, "test_good"));
  EXPECT_FALSE(contains(names, "test_wrong_abi"));
  EXPECT_FALSE(contains(names, "test_no_entry"));
  EXPECT_TRUE(contains(manager().availableNames(), "test_wrong_abi"));
}

TEST(Spelling, SuggestsCloseNamesOnly) {
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  std::vector<std::string> names{"diffuse", "dielectric", "conductor", "path"};
  EXPECT_EQ(closestMatches("difuse", names), std::vector<std::string>{"diffuse"});
  EXPECT_TRUE(closestMatches("xyz", names).empty());
  EXPECT_EQ(didYouMean("conductr", names), " (did you mean \"conductor\"?)");
  EXPECT_EQ(didYouMean("zzzzzz", names), "");
}

}  // namespace
}  // namespace femto
