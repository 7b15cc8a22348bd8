// Parameter validation of the shape, BSDF, emitter and integrator plugins:
// bad values are errors naming the scene line; defaults are Mitsuba's.
#include <gtest/gtest.h>

#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>
#include <femto/render/integrator.h>
#include <femto/xml/loader.h>

#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

ObjectRef load(const std::string& xml) {
  LoadOptions options;
  options.strict = true;
  return loadObjectFromString(xml, std::filesystem::temp_directory_path(), options, "params.xml");
}

}  // namespace

TEST(PluginParameters, PathRejectsBadDepthsNamingTheLine) {
  std::string message = errorMessageOf([] {
    load("<integrator type=\"path\" version=\"3.0.0\">\n  <integer name=\"max_depth\" value=\"-2\"/>\n</integrator>");
  });
  EXPECT_NE(message.find("params.xml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("max_depth"), std::string::npos) << message;
  message = errorMessageOf([] {
    load("<integrator type=\"path\" version=\"3.0.0\">\n  <integer name=\"rr_depth\" value=\"0\"/>\n</integrator>");
  });
  EXPECT_NE(message.find("params.xml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("rr_depth"), std::string::npos) << message;
}

TEST(PluginParameters, EveryPathIntegratorReadsDepthsWithOneRule) {
  // path, transient_path (and its mitransient names) and transient_beams
  // share PathDepthSettings: the same range, the same message, the same line.
  for (const char* integrator : {"path", "transient_path", "transient_prbvolpath", "transientpath", "transient_beams"}) {
    SCOPED_TRACE(integrator);
    const std::string open = str("<integrator type=\"", integrator, "\" version=\"3.0.0\">\n");
    std::string message =
        errorMessageOf([&] { load(open + "  <integer name=\"max_depth\" value=\"-2\"/>\n</integrator>"); });
    EXPECT_EQ(message.rfind(str("params.xml:2: parameter \"max_depth\" of \"", integrator,
                                "\": must be at least -1 (-1: no limit), got -2"), 0), 0u) << message;
    message = errorMessageOf([&] { load(open + "\n  <integer name=\"rr_depth\" value=\"0\"/>\n</integrator>"); });
    EXPECT_EQ(message.rfind(str("params.xml:3: parameter \"rr_depth\" of \"", integrator,
                                "\": must be at least 1, got 0"), 0), 0u) << message;
  }
}

TEST(PluginParameters, DepthsBeyondAnIntMeanNoLimit) {
  auto integrator = load(R"(<integrator type="path" version="3.0.0"><integer name="max_depth" value="4294967296"/>
    <integer name="rr_depth" value="3"/></integrator>)");
  const std::string text = integrator->toString();
  EXPECT_NE(text.find("max_depth=2147483647, rr_depth=3"), std::string::npos) << text;
}

TEST(PluginParameters, PathDefaultsAreMitsubas) {
  auto integrator = load(R"(<integrator type="path" version="3.0.0"/>)");
  std::string text = integrator->toString();
  EXPECT_NE(text.find("max_depth=-1"), std::string::npos) << text;
  EXPECT_NE(text.find("rr_depth=5"), std::string::npos) << text;
  EXPECT_NE(text.find("hide_emitters=false"), std::string::npos) << text;
}

TEST(PluginParameters, DiffuseDefaultReflectanceIsOneHalf) {
  auto bsdf = std::dynamic_pointer_cast<BSDF>(load(R"(<bsdf type="diffuse" version="3.0.0"/>)"));
  ASSERT_NE(bsdf, nullptr);
  SurfaceInteraction si;
  si.wi = Vec3f(0, 0, 1);
  EXPECT_NEAR(bsdf->eval(si, {0, 0, 1}).g, 0.5f * InvPi, 1e-7f);
}

TEST(PluginParameters, PointLightTakesPositionOrToWorldNotBoth) {
  std::string message = errorMessageOf([] {
    load("<emitter type=\"point\" version=\"3.0.0\">\n  <point name=\"position\" x=\"1\" y=\"0\" z=\"0\"/>\n"
         "  <transform name=\"to_world\"><translate x=\"1\"/></transform>\n</emitter>");
  });
  EXPECT_NE(message.find("params.xml:2"), std::string::npos) << message;
  EXPECT_NE(message.find("to_world"), std::string::npos) << message;
}

TEST(PluginParameters, NegativeRadianceIsAnError) {
  std::string message = errorMessageOf([] {
    load("<emitter type=\"area\" version=\"3.0.0\">\n  <rgb name=\"radiance\" value=\"1, -1, 1\"/>\n</emitter>");
  });
  EXPECT_NE(message.find("params.xml:2"), std::string::npos) << message;
}
