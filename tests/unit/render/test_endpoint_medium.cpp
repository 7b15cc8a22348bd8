// The medium an emitter or sensor sits in, written as Mitsuba 0.6 does (an
// unnamed <ref id="fog"/> or a nested <medium> inside <emitter>/<sensor>) or
// as Mitsuba 3 / femto do (a "medium" ref): the loader hands it to the
// object, and a point light in fog renders the same either way, with
// transient_path (next-event estimation from the path vertex's medium) and
// transient_beams (photons start in the emitter's medium).
#include <gtest/gtest.h>

#include <femto/render/emitter.h>
#include <femto/render/medium.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>

#include "plugin_util.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

const char* Fog06 = R"(<medium type="homogeneous" id="fog"><rgb name="sigmaS" value="0.4"/><rgb name="sigmaA" value="0.1"/></medium>)";

/// A point light and a camera in fog, in front of a diffuse wall; Mitsuba 0.6
/// spelling. `fogAtTop`: the medium declared at the top and referenced by
/// both; otherwise nested in the emitter and referenced by the sensor.
std::string scene06(bool fogAtTop) {
  return str(R"(<scene version="0.6.0">
  <integrator type="volpath"><integer name="maxDepth" value="4"/></integrator>)",
             fogAtTop ? Fog06 : "", R"(
  <emitter type="point">)", fogAtTop ? R"(<ref id="fog"/>)" : Fog06, R"(
    <point name="position" x="0.4" y="0.3" z="1.2"/><rgb name="intensity" value="4"/></emitter>
  <shape type="rectangle"><transform name="toWorld"><rotate y="1" angle="180"/><scale value="2"/><translate z="3"/></transform></shape>
  <sensor type="perspective"><float name="fov" value="60"/><ref id="fog"/>
    <sampler type="independent"><integer name="sampleCount" value="4"/></sampler>
    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/><rfilter type="box"/></film>
  </sensor>
</scene>)");
}

/// The same scene in Mitsuba 3 / femto spelling: the sensor names its
/// medium; the emitter names none (its medium follows from the geometry).
std::string scene3(const std::string& integrator) {
  return str(R"(<scene version="3.0.0">
  <integrator type=")", integrator, R"("><integer name="max_depth" value="4"/>)",
             integrator == "transient_beams" ? R"(<integer name="photon_count" value="2000"/><float name="radius" value="0.1"/>)"
                                             : "",
             R"(</integrator>
  <medium type="homogeneous" id="fog"><rgb name="sigma_s" value="0.4"/><rgb name="sigma_a" value="0.1"/></medium>
  <emitter type="point"><point name="position" x="0.4" y="0.3" z="1.2"/><rgb name="intensity" value="4"/></emitter>
  <shape type="rectangle"><transform name="to_world"><rotate y="1" angle="180"/><scale value="2"/><translate z="3"/></transform></shape>
  <sensor type="perspective"><float name="fov" value="60"/><ref name="medium" id="fog"/>
    <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/><rfilter type="box"/></film>
  </sensor>
</scene>)");
}

void expectSameImage(const Bitmap& a, const Bitmap& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(a.pixel(x, y)[c], b.pixel(x, y)[c]) << "pixel " << x << ", " << y;
        sum += a.pixel(x, y)[c];
      }
  EXPECT_GT(sum, 0.0) << "the test scene must not be black";
}

}  // namespace

TEST(EndpointMedium, Mitsuba06RefAndNestedMediumReachEmitterAndSensor) {
  for (bool fogAtTop : {true, false}) {
    SCOPED_TRACE(fogAtTop ? "<ref id=\"fog\"/> in both" : "<medium> nested in <emitter>");
    auto scene = loadSceneStrict(scene06(fogAtTop));
    ASSERT_EQ(scene->emitters().size(), 1u);
    const Medium* emitterMedium = scene->emitters()[0]->medium();
    ASSERT_NE(emitterMedium, nullptr);
    EXPECT_EQ(emitterMedium, scene->sensor().medium()) << "one medium object, shared";
    EXPECT_EQ(emitterMedium->id(), "fog");
    EXPECT_NEAR(emitterMedium->majorant().g, 0.5f, 1e-6f);  // sigmaS + sigmaA
  }
  // A <medium> nested in the <sensor>, the emitter referring to it.
  std::string nestedInSensor = scene06(true);
  nestedInSensor.replace(nestedInSensor.find(Fog06), std::string(Fog06).size(), "");
  nestedInSensor.replace(nestedInSensor.find(R"(<float name="fov" value="60"/><ref id="fog"/>)"),
                         std::string(R"(<float name="fov" value="60"/><ref id="fog"/>)").size(),
                         str(R"(<float name="fov" value="60"/>)", Fog06));
  auto scene = loadSceneStrict(nestedInSensor);
  ASSERT_NE(scene->sensor().medium(), nullptr);
  EXPECT_EQ(scene->emitters()[0]->medium(), scene->sensor().medium());
}

TEST(EndpointMedium, NamedMediumAndErrors) {
  auto scene = loadSceneStrict(R"(<scene version="3.0.0">
  <medium type="homogeneous" id="fog"><float name="sigma_t" value="1"/></medium>
  <emitter type="point"><ref name="medium" id="fog"/></emitter></scene>)");
  ASSERT_NE(scene->emitters()[0]->medium(), nullptr);
  EXPECT_EQ(scene->emitters()[0]->medium()->id(), "fog");
  EXPECT_EQ(scene->sensor().medium(), nullptr);
  std::string two = errorMessageOf([] {
    loadSceneStrict(R"(<scene version="3.0.0">
  <medium type="homogeneous" id="a"/><medium type="homogeneous" id="b"/>
  <emitter type="point"><ref id="a"/><ref id="b"/></emitter></scene>)");
  });
  EXPECT_NE(two.find("\"point\" takes at most one nested <medium>, got 2"), std::string::npos) << two;
  std::string notAMedium = errorMessageOf([] {
    loadSceneStrict(R"(<scene version="3.0.0"><bsdf type="diffuse" id="white"/>
  <emitter type="point"><ref name="medium" id="white"/></emitter></scene>)");
  });
  EXPECT_NE(notAMedium.find("parameter \"medium\" of \"point\": expected a <medium>"), std::string::npos) << notAMedium;
}

TEST(EndpointMedium, PointLightInFogRendersAsTheMitsuba3Scene) {
  auto dir = scratchDir("endpoint-medium");
  // volpath (0.6) loads as transient_path: same sampler, same seed, same image.
  auto legacy = render(loadSceneStrict(scene06(true)), dir / "legacy.exr", 7);
  auto nested = render(loadSceneStrict(scene06(false)), dir / "nested.exr", 7);
  auto own = render(loadSceneStrict(scene3("transient_path")), dir / "own.exr", 7);
  expectSameImage(legacy.steady, own.steady);
  expectSameImage(nested.steady, own.steady);
  // transient_beams: its photons start in the emitter's medium when the scene
  // names one, else in the one found around the light (here the sensor's).
  std::string beams06 = scene06(true);
  beams06.replace(beams06.find(R"(<integrator type="volpath"><integer name="maxDepth" value="4"/></integrator>)"),
                  std::string(R"(<integrator type="volpath"><integer name="maxDepth" value="4"/></integrator>)").size(),
                  R"(<integrator type="transient_beams"><integer name="maxDepth" value="4"/>)"
                  R"(<integer name="photonCount" value="2000"/><float name="radius" value="0.1"/></integrator>)");
  auto beamsLegacy = render(loadSceneStrict(beams06), dir / "beams-legacy.exr", 7);
  auto beamsOwn = render(loadSceneStrict(scene3("transient_beams")), dir / "beams-own.exr", 7);
  expectSameImage(beamsLegacy.steady, beamsOwn.steady);
}
