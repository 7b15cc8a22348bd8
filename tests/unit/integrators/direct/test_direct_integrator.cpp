// Accuracy of the `direct` integrator against closed forms (tolerances: 5
// standard errors of the estimate, see li_estimate.h), and its parameters.
#include <gtest/gtest.h>

#include "li_estimate.h"
#include "plugin_util.h"

using namespace femto;
using namespace femto::test;

namespace {

const Color3f Rho(0.3f, 0.5f, 0.8f);
const Color3f Le(1.0f, 0.5f, 2.0f);

/// The furnace of the path tests (a closed diffuse sphere of reflectance rho
/// emitting Le inside) rendered by `direct`: emission seen directly plus one
/// bounce of emitted light, L = Le (1 + rho), whatever the sample counts.
std::shared_ptr<Scene> directFurnace(const std::string& integratorParams) {
  return loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="direct">)", integratorParams, R"(</integrator>
  <shape type="sphere">
    <boolean name="flip_normals" value="true"/>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(Rho), R"("/></bsdf>
    <emitter type="area"><rgb name="radiance" value=")", rgb(Le), R"("/></emitter>
  </shape>
</scene>)"));
}

}  // namespace

TEST(DirectFurnace, EmissionPlusOneBounceForEverySampleSplit) {
  for (const char* params : {"", R"(<integer name="emitter_samples" value="3"/><integer name="bsdf_samples" value="2"/>)",
                             R"(<integer name="emitter_samples" value="0"/>)", R"(<integer name="bsdf_samples" value="0"/>)",
                             R"(<integer name="shading_samples" value="4"/>)"}) {
    SCOPED_TRACE(params);
    auto scene = directFurnace(params);
    expectWithinErrorBars(estimateLi(*scene, 20000, randomInteriorRay), Le * (Color3f(1.0f) + Rho));
  }
}

TEST(DirectFurnace, HideEmittersLeavesOnlyTheBounce) {
  auto scene = directFurnace(R"(<boolean name="hide_emitters" value="true"/>)");
  expectWithinErrorBars(estimateLi(*scene, 20000, randomInteriorRay), Le * Rho);
}

TEST(DirectPointLight, DiffusePlaneIsExact) {
  // L = rho / pi * I cos(theta) / d^2 at any point of the plane z = 0 under
  // a point light; emitter sampling finds it exactly and BSDF samples cannot,
  // so the estimate has no variance.
  const Color3f rho(0.2f, 0.5f, 0.8f), intensity(1.0f, 2.0f, 3.0f);
  const Point3f light(0.5f, -0.3f, 2.0f), eye(0.2f, 0.1f, 5.0f);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="direct"><integer name="emitter_samples" value="2"/></integrator>
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value=")", rgb(rho), R"("/></bsdf>
  </shape>
  <emitter type="point">
    <point name="position" x=")", light.x, R"(" y=")", light.y, R"(" z=")", light.z, R"("/>
    <rgb name="intensity" value=")", rgb(intensity), R"("/>
  </emitter>
</scene>)"));
  for (Point3f target : {Point3f(0, 0, 0), Point3f(0.5f, -0.3f, 0), Point3f(3, 2, 0)}) {
    SCOPED_TRACE(str("target ", target));
    Estimate e = estimateLi(*scene, 4, [&](PCG32&) { return Ray(eye, normalize(target - eye)); });
    float d = distance(light, target);
    expectWithinErrorBars(e, rho * intensity * (InvPi * (light.z / d) / (d * d)));
    EXPECT_EQ(e.standardError, Color3f(0.0f));
  }
}

TEST(DirectSphereLight, MultiSampleMISMatchesTheFormFactor) {
  // With unequal sample counts the sample-count-weighted MIS weights must
  // still sum to one.
  expectSphereLightFormFactor(
      R"(<integrator type="direct"><integer name="emitter_samples" value="1"/><integer name="bsdf_samples" value="3"/></integrator>)",
      Color3f(0.2f, 0.5f, 0.8f), {Point3f(0, 0, 0), Point3f(1.5f, 0, 0)});
}

TEST(DirectParameters, RefusesNoSamplesAtAll) {
  std::string message = errorMessageOf([] {
    directFurnace(R"(<integer name="emitter_samples" value="0"/><integer name="bsdf_samples" value="0"/>)");
  });
  EXPECT_NE(message.find("cannot both be 0"), std::string::npos) << message;
  message = errorMessageOf([] { directFurnace(R"(<integer name="bsdf_samples" value="-1"/>)"); });
  EXPECT_NE(message.find("bsdf_samples"), std::string::npos) << message;
}

TEST(DirectParameters, MitsubaZeroSixCamelCaseNamesLoad) {
  // lajolla's Veach scene (Mitsuba 0.4 syntax) names emitterSamples/bsdfSamples.
  auto scene = loadStrict(R"(<scene version="0.4.0">
  <integrator type="direct"><integer name="emitterSamples" value="4"/><integer name="bsdfSamples" value="2"/></integrator>
</scene>)");
  EXPECT_NE(scene->integrator().toString().find("emitter_samples=4, bsdf_samples=2"), std::string::npos)
      << scene->integrator().toString();
}
