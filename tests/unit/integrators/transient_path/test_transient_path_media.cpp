// transient_path in media: the OPL histogram of single scattering from a
// point light against its closed form, scattering delays, a furnace filled
// with a conservative medium, agreement with `path` without media, and
// Mitsuba volpath scenes loading in strict mode.
#include <gtest/gtest.h>

#include <femto/math/pcg32.h>
#include <femto/math/warp.h>

#include "media_test_util.h"
#include "plugin_util.h"
#include "single_scattering_model.h"
#include "transient_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

const float SigmaS = 0.6f, SigmaA = 0.2f, SigmaT = SigmaS + SigmaA;
const Point3f Light(0.8f, 0.0f, 1.0f);
const float Intensity = 2.0f;

/// Camera at the origin inside an unbounded homogeneous medium lit by a point
/// light; max_depth = 2 keeps only single scattering.
std::shared_ptr<Scene> singleScatteringScene(const std::string& phaseParams = "") {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="2"/></integrator>
  <medium id="m" type="homogeneous"><float name="sigma_s" value=")", SigmaS, R"("/><float name="sigma_a" value=")",
                             SigmaA, R"("/><phase type="isotropic">)", phaseParams, R"(</phase></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x="0.8" y="0" z="1"/><float name="intensity" value="2"/></emitter>
</scene>)"));
}

}  // namespace

TEST(TransientPathMedia, SingleScatteringOplHistogramMatchesClosedForm) {
  auto scene = singleScatteringScene();
  const TransientIntegrator& integrator = transientIntegrator(*scene);
  for (Vec3f d : {normalize(Vec3f(0.3f, 0.1f, 1.0f)), normalize(Vec3f(-1.0f, 0.5f, -0.2f))}) {
    SCOPED_TRACE(str("direction ", d));
    SingleScattering model{d, Light, Intensity, SigmaS, SigmaT};
    const double tau0 = model.tau(0.0), width = 6.0;
    const int bins = 24, n = 200000;
    std::vector<Mean> histogram(bins);
    Mean total;
    auto sampler = seededSampler(31);
    for (int i = 0; i < n; ++i) {
      CollectingRecorder recorder;
      integrator.sample(*scene, Ray(Point3f(0.0f), d), *sampler, recorder);
      // One next-event estimate from the free-flight vertex and one from the
      // equiangular vertex (MIS-weighted) per single-scattering path.
      ASSERT_GE(recorder.hits.size(), 1u);
      ASSERT_LE(recorder.hits.size(), 2u);
      std::vector<double> path(bins, 0.0);
      double sum = 0.0;
      for (const auto& [opl, value] : recorder.hits) {
        ASSERT_GE(opl, tau0 - 1e-5);
        int bin = int((opl - tau0) / width * bins);
        if (bin < bins) path[bin] += value.g;
        sum += value.g;
      }
      for (int b = 0; b < bins; ++b) histogram[b].add(path[b]);
      total.add(sum);
    }
    for (int b = 0; b < bins; ++b) {
      double t0 = tau0 + width * b / bins, t1 = tau0 + width * (b + 1) / bins;
      expectWithinErrorBars(histogram[b], model.binIntegral(t0, t1), 1e-7, str("bin ", b, " [", t0, ", ", t1, ")"));
    }
    expectWithinErrorBars(total, model.binIntegral(tau0, tau0 + 200.0), 1e-7, "all OPLs");
  }
}

TEST(TransientPathMedia, SingleScatteringPastAPointLightHasBoundedVariance) {
  // A camera ray passing at distance D = 1e-3 from the point light. Next-event
  // estimates from free-flight vertices alone give sigma_s T I / (4 pi r^2 p(t))
  // at distance r from the light, a relative second moment E[v^2] / E[v]^2 of
  // about 1 / (2 pi sigma_t T D) ~ 500 here (integral of 1/r^4 over the line
  // against the square of the integral of 1/r^2; in a medium a vertex lands
  // within r of a point light with probability ~ r^3, so over random rays the
  // variance is infinite: the fireflies of the fog Cornell box). Equiangular
  // sampling toward the light (density ~ 1/r^2, MIS-combined) makes the
  // estimate nearly constant along such a ray: its relative second moment is
  // 1 plus the spread of T(t) T(r) over the sampled angles, well below 2.
  auto scene = singleScatteringScene();
  Vec3f side = normalize(cross(Vec3f(Light), Vec3f(0.0f, 1.0f, 0.0f)));
  Vec3f d = normalize(Vec3f(Light) + 1e-3f * side);
  ASSERT_NEAR(length(cross(Vec3f(Light), d)), 1e-3, 2e-5) << "distance from the light to the ray";
  // The closed form's Simpson rule in s (step 0.01) cannot resolve a peak of
  // width D: integrate in the angle theta seen from the light instead
  // (s = delta + D tan theta, ds / l^2 = dtheta / D), where the integrand
  // sigma_s / (4 pi) I exp(-sigma_t (s + l)) / D is smooth.
  const double delta = dot(Vec3f(Light), d), height = length(cross(Vec3f(Light), d));
  const double thetaA = std::atan2(-delta, height), thetaB = std::atan2(1.0, 0.0);
  auto integrand = [&](double theta) {
    double c = std::cos(theta);
    if (c <= 0.0) return 0.0;
    double sAlong = delta + height * std::tan(theta), l = height / c;
    return SigmaS * Inv4Pi * Intensity * std::exp(-SigmaT * (sAlong + l)) / height;
  };
  const int steps = 20000;  // Simpson, even
  double h = (thetaB - thetaA) / steps, expected = integrand(thetaA) + integrand(thetaB);
  for (int k = 1; k < steps; ++k) expected += (k % 2 ? 4.0 : 2.0) * integrand(thetaA + k * h);
  expected *= h / 3.0;
  auto sampler = seededSampler(53);
  Mean value, square;
  for (int i = 0; i < 20000; ++i) {
    CollectingRecorder recorder;
    transientIntegrator(*scene).sample(*scene, Ray(Point3f(0.0f), d), *sampler, recorder);
    double sum = 0.0;
    for (const auto& [opl, v] : recorder.hits) sum += v.g;
    value.add(sum);
    square.add(sum * sum);
  }
  expectWithinErrorBars(value, expected, 1e-4 * expected, "single scattering past the light");
  EXPECT_LT(square.mean() / (expected * expected), 2.0) << "relative second moment " << square.mean() / (expected * expected);
}

TEST(TransientPathMedia, ScatteringDelayShiftsTheOpl) {
  // A constant delay of 0.5 per scattering event shifts every single-scattering
  // contribution by 0.5; an exponential lifetime of mean 0.3 adds 0.3 on average.
  const Vec3f d = normalize(Vec3f(0.3f, 0.1f, 1.0f));
  auto meanOpl = [&](const std::string& phaseParams) {
    auto scene = singleScatteringScene(phaseParams);
    auto sampler = seededSampler(41);
    Mean m;
    for (int i = 0; i < 40000; ++i) {
      CollectingRecorder recorder;
      transientIntegrator(*scene).sample(*scene, Ray(Point3f(0.0f), d), *sampler, recorder);
      for (const auto& [opl, value] : recorder.hits) m.add(opl);
    }
    return m;
  };
  Mean plain = meanOpl(""), delayed = meanOpl(R"(<float name="delay" value="0.5"/><float name="lifetime" value="0.3"/>)");
  double se = std::sqrt(plain.standardError() * plain.standardError() + delayed.standardError() * delayed.standardError());
  EXPECT_NEAR(delayed.mean() - plain.mean(), 0.8, 5.0 * se);
}

namespace {

/// A closed sphere (radius 1) with diffuse reflectance rho emitting Le, filled
/// with a non-absorbing medium, the camera inside it. A uniform radiance field
/// L satisfies both the RTE (albedo 1: in-scattering replaces extinction) and
/// the boundary condition L = Le + rho L, so L = Le / (1 - rho) everywhere.
std::shared_ptr<Scene> mediumFurnace(const std::string& phase) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"/>
  <medium id="m" type="homogeneous"><float name="sigma_t" value="1.5"/><float name="albedo" value="1"/>)",
                             phase, R"(</medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <shape type="sphere">
    <boolean name="flip_normals" value="true"/>
    <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf>
    <emitter type="area"><float name="radiance" value="1"/></emitter>
    <ref name="interior" id="m"/><ref name="exterior" id="m"/>
  </shape>
</scene>)"));
}

}  // namespace

TEST(TransientPathMedia, FurnaceWithConservativeMedium) {
  for (const char* phase : {"", R"(<phase type="hg"><float name="g" value="0.6"/></phase>)"}) {
    SCOPED_TRACE(phase);
    auto scene = mediumFurnace(phase);
    auto sampler = seededSampler(51);
    PCG32 rng(3, 5);
    Mean L;
    for (int i = 0; i < 20000; ++i) {
      Point3f o = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()}) * (0.5f * rng.nextFloat());
      Ray ray(o, warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()}));
      CollectingRecorder recorder;
      transientIntegrator(*scene).sample(*scene, ray, *sampler, recorder);
      for (const auto& [opl, value] : recorder.hits) ASSERT_GT(opl, 0.0);
      L.add(recorder.total().r);
    }
    expectWithinErrorBars(L, 2.0, 1e-4, "furnace radiance");
  }
}

TEST(TransientPathMedia, SteadyResultEqualsPathWithoutMedia) {
  // An area light (sphere), a diffuse floor and a diffuse box: transient_path's
  // contributions summed over OPL estimate the same radiance as `path`.
  auto sceneXml = [](const char* integrator) {
    return str(R"(<scene version="3.0.0"><integrator type=")", integrator, R"("/>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.7, 0.5, 0.3"/></bsdf></shape>
  <shape type="cube"><transform name="to_world"><scale value="0.5"/><translate x="0.5" z="0.5"/></transform>
    <bsdf type="diffuse"><float name="reflectance" value="0.6"/></bsdf></shape>
  <shape type="sphere"><point name="center" x="-0.5" y="0.2" z="2"/><float name="radius" value="0.4"/>
    <emitter type="area"><rgb name="radiance" value="4, 5, 6"/></emitter></shape>
</scene>)");
  };
  auto transient = loadSceneStrict(sceneXml("transient_path")), steady = loadSceneStrict(sceneXml("path"));
  auto path = dynamic_cast<const SamplingIntegrator*>(&steady->integrator());
  ASSERT_NE(path, nullptr);
  auto samplerA = seededSampler(61), samplerB = seededSampler(62);
  PCG32 rng(7, 9);
  Mean a[3], b[3];
  for (int i = 0; i < 20000; ++i) {
    Point3f target(4.0f * rng.nextFloat() - 2.0f, 4.0f * rng.nextFloat() - 2.0f, 0.0f);
    Ray ray(Point3f(0.3f, -3.0f, 2.5f), normalize(target - Point3f(0.3f, -3.0f, 2.5f)));
    CollectingRecorder recorder;
    transientIntegrator(*transient).sample(*transient, ray, *samplerA, recorder);
    Color3f Lt = recorder.total(), Lp = path->Li(ray, *steady, *samplerB);
    for (int c = 0; c < 3; ++c) {
      a[c].add(Lt[c]);
      b[c].add(Lp[c]);
    }
  }
  for (int c = 0; c < 3; ++c) {
    double se = std::sqrt(a[c].standardError() * a[c].standardError() + b[c].standardError() * b[c].standardError());
    EXPECT_NEAR(a[c].mean(), b[c].mean(), 5.0 * se) << "channel " << c;
  }
}

TEST(TransientPathMedia, VolpathScenesLoadStrictly) {
  const std::filesystem::path file = std::filesystem::path(FEMTO_SOURCE_DIR) / "../shared/scenes/lajolla-vol-cbox-fog-0.5/vol_cbox.xml";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is not present";
  auto scene = loadSceneStrict("<scene version=\"3.0.0\"/>");  // puts the build's plugins on the search path
  LoadOptions options;
  options.strict = true;
  scene = loadScene(file, options);
  EXPECT_NE(scene->integrator().toString().find("TransientPathIntegrator"), std::string::npos);
  ASSERT_NE(scene->sensor().medium(), nullptr);
  EXPECT_NEAR(scene->sensor().medium()->majorant().r, 0.0015f, 1e-7f);
  for (const auto& shape : scene->shapes()) EXPECT_EQ(shape->exteriorMedium(), scene->sensor().medium());
}

TEST(TransientPathMedia, VolpathMapsToTransientPathInBothDialects) {
  for (const char* version : {"0.6.0", "3.0.0"}) {
    auto scene = loadSceneStrict(str(R"(<scene version=")", version, R"("><integrator type="volpath"/></scene>)"));
    EXPECT_NE(scene->integrator().toString().find("TransientPathIntegrator"), std::string::npos) << version;
  }
}
