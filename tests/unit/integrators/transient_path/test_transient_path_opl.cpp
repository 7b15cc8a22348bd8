// transient_path reports each contribution at its exact optical path length:
// a point light over a diffuse plane (with and without observer time), the
// delay of a glass slab, a medium's refractive index, and the film's horizon.
#include <gtest/gtest.h>

#include <femto/render/bsdf.h>
#include <femto/render/emitter.h>

#include "media_test_util.h"
#include "plugin_util.h"
#include "transient_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

const Point3f Light(0.5f, -0.3f, 2.0f);
const Color3f Intensity(1.0f, 2.0f, 3.0f);
const Color3f Rho(0.2f, 0.5f, 0.8f);

std::shared_ptr<Scene> planeScene(const std::string& integratorParams, const std::string& extra = "",
                                  const std::string& bsdfParams = "") {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path">)", integratorParams, R"(</integrator>
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.5, 0.8"/>)", bsdfParams, R"(</bsdf>
  </shape>
  <emitter type="point"><point name="position" x="0.5" y="-0.3" z="2"/><rgb name="intensity" value="1, 2, 3"/></emitter>
  )", extra, "</scene>"));
}

/// Radiance the plane reflects at x toward any viewer: rho / pi * I cos(theta) / d^2.
Color3f planeRadiance(const Point3f& x) {
  float d = distance(Light, x);
  return Rho * InvPi * Intensity * (Light.z / d) / (d * d);
}

}  // namespace

TEST(TransientPathOPL, PointLightOverPlaneIsExact) {
  const Point3f camera(1.0f, 2.0f, 3.0f);
  // observer_time = false and mitransient's camera_unwarp = true both drop the camera segment.
  for (const char* params : {R"(<boolean name="observer_time" value="true"/>)", R"(<boolean name="observer_time" value="false"/>)",
                             R"(<boolean name="camera_unwarp" value="true"/><string name="temporal_filter" value="box"/>)"}) {
    SCOPED_TRACE(params);
    bool observerTime = std::string(params).find("\"observer_time\" value=\"true\"") != std::string::npos;
    auto scene = planeScene(params);
    auto sampler = seededSampler(3);
    for (Point3f x : {Point3f(0.2f, 0.4f, 0.0f), Point3f(-1.5f, 0.7f, 0.0f), Point3f(3.0f, -2.0f, 0.0f)}) {
      CollectingRecorder recorder;
      transientIntegrator(*scene).sample(*scene, Ray(camera, normalize(x - camera)), *sampler, recorder);
      ASSERT_EQ(recorder.hits.size(), 1u) << "next-event estimation is the only contribution";
      double expectedOpl = distance(Light, x) + (observerTime ? distance(x, camera) : 0.0f);
      EXPECT_NEAR(recorder.hits[0].first, expectedOpl, 1e-5 * expectedOpl);
      Color3f expected = planeRadiance(x);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(recorder.hits[0].second[c], expected[c], 1e-5f * expected[c]);
    }
  }
}

// Every BSDF takes a scattering delay (constant + exponential lifetime): it
// shifts the light scattered at the plane and leaves its value alone.
TEST(TransientPathOPL, BsdfScatteringDelayShiftsTheReflectedLight) {
  const Point3f camera(1.0f, 2.0f, 3.0f), x(0.2f, 0.4f, 0.0f);
  const Ray ray(camera, normalize(x - camera));
  const double undelayed = distance(Light, x) + distance(x, camera);
  auto constant = planeScene("", "", R"(<float name="delay" value="0.3"/>)");
  auto sampler = seededSampler(4);
  CollectingRecorder once;
  transientIntegrator(*constant).sample(*constant, ray, *sampler, once);
  ASSERT_EQ(once.hits.size(), 1u);
  EXPECT_NEAR(once.hits[0].first, undelayed + 0.3, 1e-5 * undelayed);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(once.hits[0].second[c], planeRadiance(x)[c], 1e-5f);

  // delay 0.1 + Exp(mean 0.2): the mean shift is 0.3 (5 sigma of the sample
  // mean, sigma = 0.2 / sqrt(n)), and nothing arrives before the constant part.
  auto fluorescent = planeScene("", "", R"(<float name="delay" value="0.1"/><float name="lifetime" value="0.2"/>)");
  const int n = 4000;
  double sum = 0.0, earliest = Infinity;
  for (int i = 0; i < n; ++i) {
    CollectingRecorder recorder;
    transientIntegrator(*fluorescent).sample(*fluorescent, ray, *sampler, recorder);
    ASSERT_EQ(recorder.hits.size(), 1u);
    double shift = recorder.hits[0].first - undelayed;
    sum += shift;
    earliest = std::min(earliest, shift);
  }
  EXPECT_NEAR(sum / n, 0.3, 5.0 * 0.2 / std::sqrt(double(n)));
  EXPECT_GE(earliest, 0.1 - 1e-5);
  EXPECT_THROW(planeScene("", "", R"(<float name="delay" value="-1"/>)"), Error);
}

TEST(TransientPathOPL, ContradictoryOrUnsupportedTimeParametersAreErrors) {
  std::string m = errorMessageOf([] {
    planeScene(R"(<boolean name="observer_time" value="false"/><boolean name="camera_unwarp" value="true"/>)");
  });
  EXPECT_NE(m.find("not both"), std::string::npos) << m;
  // mitransient's "gaussian" is supported (it becomes the film's time
  // filter: test_loader_dialects.cpp); other names are not.
  m = errorMessageOf([] { planeScene(R"(<string name="temporal_filter" value="tent"/>)"); });
  EXPECT_NE(m.find("temporal_filter"), std::string::npos) << m;
}

TEST(TransientPathOPL, HorizonStopsPaths) {
  auto scene = planeScene("");
  auto sampler = seededSampler(4);
  const Point3f camera(1.0f, 2.0f, 3.0f), x(0.2f, 0.4f, 0.0f);
  double opl = distance(Light, x) + distance(x, camera);
  CollectingRecorder before(opl * 0.999), after(opl * 1.001);
  transientIntegrator(*scene).sample(*scene, Ray(camera, normalize(x - camera)), *sampler, before);
  transientIntegrator(*scene).sample(*scene, Ray(camera, normalize(x - camera)), *sampler, after);
  EXPECT_TRUE(before.hits.empty());
  EXPECT_EQ(after.hits.size(), 1u);
}

namespace {

/// A test double for glass: an interface that always refracts (Snell's law,
/// no Fresnel reflection, weight 1), reporting the relative IOR crossed in
/// BSDFSample::eta as dielectrics do (int/ext entering, ext/int leaving).
class RefractingInterface final : public BSDF {
 public:
  explicit RefractingInterface(float eta) : eta_(eta) {}
  uint32_t flags() const override { return BSDFFlags::DeltaTransmission; }
  Color3f sample(const SurfaceInteraction& si, float, const Point2f&, BSDFSample& bs, TransportMode) const override {
    bs = BSDFSample();
    float cosI = Frame::cosTheta(si.wi);
    float eta = cosI > 0.0f ? eta_ : 1.0f / eta_;
    float r = 1.0f / eta, sin2T = r * r * (1.0f - cosI * cosI);
    if (sin2T >= 1.0f) return Color3f(0.0f);  // total internal reflection: absorbed by this double
    float cosT = std::sqrt(1.0f - sin2T);
    bs.wo = -si.wi * r + Vec3f(0, 0, 1) * (r * cosI - std::copysign(cosT, cosI));
    bs.pdf = 1.0f;
    bs.eta = eta;
    bs.sampledFlags = BSDFFlags::DeltaTransmission;
    return Color3f(1.0f);
  }
  Color3f eval(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return Color3f(0.0f); }
  float pdf(const SurfaceInteraction&, const Vec3f&, TransportMode) const override { return 0.0f; }

 private:
  float eta_;
};

std::shared_ptr<Shape> rectangle(const Transform& toWorld, std::shared_ptr<BSDF> bsdf, bool flip = false) {
  Properties props("rectangle");
  props.setTransform("to_world", toWorld);
  props.setBool("flip_normals", flip);
  props.setObject("bsdf", bsdf);
  return makePlugin<Shape>(ObjectKind::Shape, props);
}

/// A floor (diffuse, z = -3) lit by a point light below a glass slab of
/// thickness h (z in [-h, 0]) when eta > 0, or without the slab.
std::shared_ptr<Scene> slabScene(float eta, float h) {
  Properties diffuseProps("diffuse");
  diffuseProps.setColor("reflectance", Rho);
  auto diffuse = makePlugin<BSDF>(ObjectKind::BSDF, diffuseProps);
  Properties scene("scene");
  scene.setObject("floor", rectangle(Transform::translate(Vec3f(0, 0, -3)) * Transform::scale(Vec3f(20.0f)), diffuse));
  if (eta > 0.0f) {
    auto glass = std::make_shared<RefractingInterface>(eta);
    scene.setObject("top", rectangle(Transform::scale(Vec3f(5.0f)), glass));
    scene.setObject("bottom", rectangle(Transform::translate(Vec3f(0, 0, -h)) * Transform::scale(Vec3f(5.0f)), glass, true));
  }
  Properties light("point");
  light.setPoint("position", Point3f(0.8f, 0.0f, -2.0f));
  light.setColor("intensity", Intensity);
  scene.setObject("light", makePlugin<Emitter>(ObjectKind::Emitter, light));
  scene.setObject("integrator", makePlugin<Integrator>(ObjectKind::Integrator, Properties("transient_path")));
  return std::make_shared<Scene>(scene);
}

}  // namespace

TEST(TransientPathOPL, GlassSlabDelaysByEtaMinusOneTimesThickness) {
  const float eta = 1.5f, h = 0.4f;
  const Ray ray(Point3f(0, 0, 2), Vec3f(0, 0, -1));  // normal incidence: the path is straight
  auto sampler = seededSampler(6);
  auto vacuum = slabScene(0.0f, h), glass = slabScene(eta, h);
  CollectingRecorder direct, delayed;
  transientIntegrator(*vacuum).sample(*vacuum, ray, *sampler, direct);
  transientIntegrator(*glass).sample(*glass, ray, *sampler, delayed);
  ASSERT_EQ(direct.hits.size(), 1u);
  ASSERT_EQ(delayed.hits.size(), 1u);
  double light = distance(Point3f(0.8f, 0.0f, -2.0f), Point3f(0, 0, -3));
  EXPECT_NEAR(direct.hits[0].first, 5.0 + light, 1e-5);
  EXPECT_NEAR(delayed.hits[0].first - direct.hits[0].first, (eta - 1.0) * h, 1e-5);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(delayed.hits[0].second[c], direct.hits[0].second[c], 1e-6f);
}

TEST(TransientPathOPL, MediumIndexScalesTheOplAndAbsorptionAttenuates) {
  // A non-scattering, non-absorbing medium of index 1.33 around everything:
  // every segment's OPL is multiplied by eta. An absorbing medium attenuates
  // the value by exp(-sigma_a (camera + light distance)) in expectation.
  const Point3f camera(1.0f, 2.0f, 3.0f), x(0.2f, 0.4f, 0.0f);
  const float eta = 1.33f, sigmaA = 0.1f;
  auto scene = loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"/>
  <medium id="m" type="homogeneous"><float name="sigma_s" value="0"/><float name="sigma_a" value=")", sigmaA,
                                   R"("/><float name="eta" value=")", eta, R"("/></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale value="20"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.5, 0.8"/></bsdf>
    <ref name="exterior" id="m"/>
  </shape>
  <emitter type="point"><point name="position" x="0.5" y="-0.3" z="2"/><rgb name="intensity" value="1, 2, 3"/></emitter>
</scene>)"));
  // The camera segment is sampled (free-flight sampling ends the path where it
  // would be absorbed, with probability 1 - exp(-sigma_a |x - camera|)); the
  // light segment's transmittance is computed in closed form.
  auto sampler = seededSampler(8);
  double cameraDistance = distance(x, camera), lightDistance = distance(Light, x);
  Color3f expected = planeRadiance(x) * std::exp(-sigmaA * float(lightDistance));
  Mean reached;
  for (int i = 0; i < 20000; ++i) {
    CollectingRecorder recorder;
    transientIntegrator(*scene).sample(*scene, Ray(camera, normalize(x - camera)), *sampler, recorder);
    ASSERT_LE(recorder.hits.size(), 1u);
    reached.add(double(recorder.hits.size()));
    if (recorder.hits.empty()) continue;
    EXPECT_NEAR(recorder.hits[0].first, eta * (cameraDistance + lightDistance), 1e-5 * eta * (cameraDistance + lightDistance));
    // Shadow rays start RayEpsilon (1e-4, relative to the scene scale) off
    // the surface, so the medium they cross is that much shorter.
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(recorder.hits[0].second[c], expected[c], 2e-4f * expected[c]);
  }
  expectWithinErrorBars(reached, std::exp(-sigmaA * cameraDistance), 1e-6, "fraction of paths reaching the plane");
}

TEST(TransientPathOPL, DielectricSlabDelaysTransmittedLight) {
  // The same slab with the `dielectric` plugin (IOR 1.5 in vacuum). With
  // max_depth = 4 only the path refracted twice reaches the floor and its
  // light, at OPL 5 + (eta - 1) h + |light - floor|; Fresnel reflection at
  // normal incidence, R = ((eta - 1) / (eta + 1))^2, leaves (1 - R)^2 of the
  // vacuum radiance on average (the 1/eta^2 radiance scalings cancel).
  const float eta = 1.5f, h = 0.4f;
  auto scene = loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="4"/></integrator>
  <bsdf type="dielectric" id="glass"><float name="int_ior" value=")", eta, R"("/><float name="ext_ior" value="1"/></bsdf>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/></transform><ref id="glass"/></shape>
  <shape type="rectangle"><boolean name="flip_normals" value="true"/>
    <transform name="to_world"><scale value="5"/><translate z=")", -h, R"("/></transform><ref id="glass"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="20"/><translate z="-3"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.5, 0.8"/></bsdf></shape>
  <emitter type="point"><point name="position" x="0.8" y="0" z="-2"/><rgb name="intensity" value="1, 2, 3"/></emitter>
</scene>)"));
  const Ray ray(Point3f(0, 0, 2), Vec3f(0, 0, -1));
  const Point3f floor(0, 0, -3), light(0.8f, 0.0f, -2.0f);
  float d = distance(light, floor);
  Color3f vacuum = Rho * InvPi * Intensity * ((light.z - floor.z) / d) / (d * d);
  double expectedOpl = 5.0 + (eta - 1.0) * h + d;
  float R = (eta - 1.0f) * (eta - 1.0f) / ((eta + 1.0f) * (eta + 1.0f));
  auto sampler = seededSampler(10);
  Mean value;
  for (int i = 0; i < 20000; ++i) {
    CollectingRecorder recorder;
    transientIntegrator(*scene).sample(*scene, ray, *sampler, recorder);
    ASSERT_LE(recorder.hits.size(), 1u);
    for (const auto& [opl, v] : recorder.hits) EXPECT_NEAR(opl, expectedOpl, 1e-5 * expectedOpl);
    value.add(recorder.hits.empty() ? 0.0 : recorder.hits[0].second.g);
  }
  expectWithinErrorBars(value, (1.0 - R) * (1.0 - R) * vacuum.g, 1e-6, "transmitted radiance");
}
