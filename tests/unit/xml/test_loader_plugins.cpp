// The public loader with real plugins (from FEMTO_PLUGIN_DIR): unknown
// plugins, plugins of the wrong kind, and unused parameters a real plugin
// did not read. Skipped when the plugins are not built.
#include <filesystem>

#include <femto/core/plugin.h>
#include <femto/render/scene.h>

#include "loader_test_support.h"

using namespace femto;

namespace {
bool pluginBuilt(const std::string& name) {
  return std::filesystem::exists(std::filesystem::path(FEMTO_PLUGIN_DIR) / pluginFileName(name));
}

/// Built and loadable (a plugin may need core code that has not landed yet).
bool havePlugin(const std::string& name) {
  if (!pluginBuilt(name)) return false;
  PluginManager::instance().prependSearchPath(FEMTO_PLUGIN_DIR);
  try {
    PluginManager::instance().load(name);
    return true;
  } catch (const Error&) {
    return false;
  }
}

ObjectRef load(const std::string& xml, const LoadOptions& options = {}) {
  PluginManager::instance().prependSearchPath(FEMTO_PLUGIN_DIR);
  return loadObjectFromString(xml, ".", options, "test.xml");
}
}  // namespace

TEST(LoaderPlugins, CreatesARealPlugin) {
  if (!havePlugin("diffuse")) GTEST_SKIP() << "diffuse plugin not loadable";
  LoadOptions strict;
  strict.strict = true;
  ObjectRef bsdf =
      load("<bsdf type=\"diffuse\" id=\"white\">\n  <rgb name=\"reflectance\" value=\"0.5\"/>\n</bsdf>", strict);
  ASSERT_TRUE(bsdf);
  EXPECT_EQ(bsdf->kind(), ObjectKind::BSDF);
  EXPECT_EQ(bsdf->id(), "white");
}

TEST(LoaderPlugins, UnknownPluginSuggestsCloseNames) {
  if (!pluginBuilt("diffuse")) GTEST_SKIP() << "diffuse plugin not built";
  std::string message = loadertest::errorOf([] { load("<bsdf type=\"difuse\"/>"); });
  EXPECT_EQ(message,
            "test.xml:1: unknown <bsdf> plugin \"difuse\" (did you mean \"diffuse\"?)\n"
            "    <bsdf type=\"difuse\"/>");
}

TEST(LoaderPlugins, PluginOfTheWrongKindIsAnError) {
  if (!havePlugin("diffuse")) GTEST_SKIP() << "diffuse plugin not loadable";
  EXPECT_SCENE_ERROR(load("<shape type=\"sphere\">\n  <emitter type=\"diffuse\"/>\n</shape>"), "test.xml:2",
                     "plugin \"diffuse\" creates a <bsdf>, but it is used here as a <emitter>");
}

TEST(LoaderPlugins, UnusedParameterOfARealPlugin) {
  if (!havePlugin("diffuse")) GTEST_SKIP() << "diffuse plugin not loadable";
  LoadOptions strict;
  strict.strict = true;
  std::string message = loadertest::errorOf(
      [&] { load("<bsdf type=\"diffuse\">\n  <rgb name=\"reflectanse\" value=\"0.5\"/>\n</bsdf>", strict); });
  EXPECT_EQ(message.rfind("test.xml:2: parameter \"reflectanse\" of \"diffuse\" was not used "
                          "(did you mean \"reflectance\"?)",
                          0),
            0u)
      << message;
}

TEST(LoaderPlugins, BadValueInARealSceneIsReportedAtItsLine) {
  if (!havePlugin("sphere")) GTEST_SKIP() << "sphere plugin not loadable";
  EXPECT_SCENE_ERROR(load("<shape type=\"sphere\">\n\n  <float name=\"radius\" value=\"abc\"/>\n</shape>"),
                     "test.xml:3", "expected a number, got 'abc'");
}

TEST(LoaderPlugins, LoadsASharedSceneWithIncludes) {
  const char* file = "/work/shared/scenes/m3data-cbox-rgb-includes/cbox-rgb.xml";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared scene corpus";
  for (const char* name : {"path", "perspective", "independent", "hdrfilm", "box", "obj", "diffuse", "area"})
    if (!havePlugin(name)) GTEST_SKIP() << name << " plugin not loadable";
  LoadOptions options;
  options.resolution = Point2i(8, 8);
  options.sampleCount = 1;
  auto scene = loadScene(file, options);
  ASSERT_TRUE(scene);
  EXPECT_GE(scene->shapes().size(), 6u);
  EXPECT_EQ(scene->emitters().size(), 1u);  // the area emitter declared at the top belongs to its shape
}

TEST(LoaderPlugins, UnknownPluginWithoutCloseMatchNamesTheSearchPath) {
  try {
    femto::loadObjectFromString("<bsdf type=\"zzzqqq\"/>", ".", {}, "test.xml");
    FAIL() << "expected an error";
  } catch (const femto::Error& e) {
    std::string message = e.what();
    EXPECT_NE(message.find("test.xml:1: unknown <bsdf> plugin \"zzzqqq\" (no zzzqqq.so in "), std::string::npos)
        << message;
    for (const auto& dir : femto::PluginManager::instance().searchPath())
      EXPECT_NE(message.find(dir.string()), std::string::npos) << message;
  }
}

// --resolution and --spp reach the film, sampler and sensor a scene gets by
// default (Mitsuba's hdrfilm, independent, perspective), not only written ones.
TEST(LoaderPlugins, OverridesReachTheDefaultFilmSamplerAndSensor) {
  for (const char* name : {"perspective", "independent", "hdrfilm", "sphere", "constant"})
    if (!havePlugin(name)) GTEST_SKIP() << name << " plugin not loadable";
  LoadOptions options;
  options.resolution = Point2i(12, 7);
  options.sampleCount = 3;
  const std::string lit = "<shape type=\"sphere\"/><emitter type=\"constant\"/>";
  for (const std::string& sensor :
       {std::string(), std::string("<sensor type=\"perspective\"/>"),
        std::string("<sensor type=\"perspective\"><film type=\"hdrfilm\"/></sensor>"),
        std::string("<sensor type=\"perspective\"><sampler type=\"independent\"/></sensor>")}) {
    SCOPED_TRACE(sensor.empty() ? "no <sensor>" : sensor);
    auto scene = loadSceneFromString("<scene version=\"3.0.0\">" + sensor + lit + "</scene>", ".", options);
    ASSERT_TRUE(scene);
    EXPECT_EQ(scene->sensor().film().size(), Point2i(12, 7));
    EXPECT_EQ(scene->sensor().sampler().sampleCount(), 3u);
  }
  // A sensor nested in a shape is the scene's: no default camera beside it.
  if (havePlugin("irradiancemeter") && havePlugin("rectangle")) {
    auto nested = loadSceneFromString(
        "<scene version=\"3.0.0\"><shape type=\"rectangle\"><sensor type=\"irradiancemeter\"/></shape>" + lit +
            "</scene>",
        ".", options);
    EXPECT_NE(nested->sensor().toString().find("rradiance"), std::string::npos) << nested->sensor().toString();
    EXPECT_EQ(nested->sensor().film().size(), Point2i(12, 7));
  }
  // Without overrides the defaults are Mitsuba's (768 x 576, 4 samples).
  auto plain = loadSceneFromString("<scene version=\"3.0.0\">" + lit + "</scene>", ".", {});
  EXPECT_EQ(plain->sensor().film().size(), Point2i(768, 576));
  EXPECT_EQ(plain->sensor().sampler().sampleCount(), 4u);
}
