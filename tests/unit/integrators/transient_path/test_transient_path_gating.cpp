// transient_path's time gating (time_gating = true): next-event vertices
// toward point lights sampled only where their contributions reach the
// film's window. Against the closed form of single scattering in a late
// window (and its variance against the ungated estimator's), and against the
// ungated estimator on randomised bounded-media scenes (independent
// estimators of the same window, within their noise).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/math/warp.h>
#include <femto/transport/equiangular.h>
#include <femto/transport/time_gate.h>

#include "media_test_util.h"
#include "plugin_util.h"
#include "single_scattering_model.h"
#include "transient_test_util.h"
#include "window_estimate.h"

using namespace femto;
using namespace femto::test;

namespace {

const float SigmaS = 0.6f, SigmaA = 0.2f, SigmaT = SigmaS + SigmaA;
const Point3f Light(0.8f, 0.0f, 1.0f);
const float Intensity = 2.0f;

/// Camera at the origin inside an unbounded homogeneous medium lit by a point
/// light; max_depth = 2 keeps only single scattering.
std::shared_ptr<Scene> singleScatteringScene(bool gating) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="2"/>
    <boolean name="time_gating" value=")",
                             gating ? "true" : "false", R"("/></integrator>
  <medium id="m" type="homogeneous"><float name="sigma_s" value=")",
                             SigmaS, R"("/><float name="sigma_a" value=")", SigmaA, R"("/></medium>
  <sensor type="perspective"><ref id="m"/></sensor>
  <emitter type="point"><point name="position" x="0.8" y="0" z="1"/><float name="intensity" value="2"/></emitter>
</scene>)"));
}

}  // namespace

TEST(TransientPathGating, LateWindowOfSingleScatteringMatchesClosedFormWithLowerVariance) {
  const Vec3f d = normalize(Vec3f(0.3f, 0.1f, 1.0f));
  SingleScattering model{d, Light, Intensity, SigmaS, SigmaT};
  // A window late in the decay: from 1.5 to 2.5 past the first arrival.
  TimeGrid grid{model.tau(0.0) + 1.5, 0.125, 8};
  const int n = 40000;
  auto ray = [&](PCG32&) { return Ray(Point3f(0.0f), d); };
  auto gatedScene = singleScatteringScene(true), ungatedScene = singleScatteringScene(false);
  WindowEstimate gated = estimateWindow(*gatedScene, grid, n, 5, ray);
  WindowEstimate ungated = estimateWindow(*ungatedScene, grid, n, 6, ray);
  for (int b = 0; b < grid.bins; ++b) {
    double t0 = grid.start + b * grid.binWidth, t1 = t0 + grid.binWidth;
    expectWithinErrorBars(gated.bins[b], model.binIntegral(t0, t1), 1e-7, str("gated bin ", b));
  }
  double expected = model.binIntegral(grid.start, grid.end());
  expectWithinErrorBars(gated.total, expected, 1e-7, "gated window");
  expectWithinErrorBars(ungated.total, expected, 1e-7, "ungated window");
  // Ungated, the equiangular vertex lands in the window with the probability
  // P its density gives the window's distance range (a few per cent here),
  // and free-flight vertices with about sigma_t T(s) ds there; gated, every
  // equiangular vertex lands in it. The estimate of the window's content is
  // then nearly constant per sample, against a value 1/P times larger with
  // probability ~P ungated: a variance ~1/P times lower. Half of 1/P is asked.
  EquiangularSegment whole = equiangularSegment(Point3f(0.0f), d, Infinity, Light);
  DistanceRange inWindow = distancesArrivingWithin(Point3f(0.0f), d, Light, grid.start, grid.end());
  double p = 0.0;
  const int steps = 2000;
  for (int k = 0; k < steps; ++k) {
    double t = inWindow.t0 + (k + 0.5) / steps * (inWindow.t1 - inWindow.t0);
    p += pdfEquiangular(whole, float(t)) * (inWindow.t1 - inWindow.t0) / steps;
  }
  ASSERT_LT(p, 0.1) << "the window is a small part of the equiangular density";
  double ratio = std::pow(ungated.total.standardError() / gated.total.standardError(), 2);
  EXPECT_GT(ratio, 0.5 / p) << "variance ungated / gated, equiangular share of the window P = " << p;
}

TEST(TransientPathGating, GatedWindowAgreesWithUngatedOnRandomisedMediaScenes) {
  // A fog cube (index-matched, random coefficients) holding a diffuse floor
  // and a point light at a random place, seen from outside; late windows of
  // multiple scattering, where no closed form exists: the gated and the
  // ungated estimators (independent random numbers) must agree within their
  // combined noise.
  PCG32 scenes(2024, 1);
  for (int k = 0; k < 3; ++k) {
    float sigmaT = 0.3f + 1.2f * scenes.nextFloat(), albedo = 0.5f + 0.45f * scenes.nextFloat();
    Point3f light(scenes.nextFloat() - 0.5f, 0.2f + 0.6f * scenes.nextFloat(), scenes.nextFloat() - 0.5f);
    double start = 5.0 + 2.0 * scenes.nextFloat();
    SCOPED_TRACE(str("scene ", k, ": sigma_t ", sigmaT, " albedo ", albedo, " light ", light, " window from ", start));
    auto scene = [&](bool gating) {
      return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="6"/>
    <boolean name="time_gating" value=")",
                                 gating ? "true" : "false", R"("/></integrator>
  <medium id="fog" type="homogeneous"><rgb name="sigma_t" value=")",
                                 sigmaT, R"("/><rgb name="albedo" value=")", albedo, R"("/></medium>
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.95"/><rotate x="1" angle="-90"/><translate y="-0.95"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.7"/></bsdf>
  </shape>
  <emitter type="point"><point name="position" x=")",
                                 light.x, R"(" y=")", light.y, R"(" z=")", light.z,
                                 R"("/><float name="intensity" value="3"/></emitter>
  <sensor type="perspective"><transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform></sensor>
</scene>)"));
    };
    TimeGrid grid{start, 0.25, 4};
    auto rays = [](PCG32& rng) {
      Point3f target(rng.nextFloat() * 1.6f - 0.8f, rng.nextFloat() * 1.6f - 0.8f, 0.0f);
      return Ray(Point3f(0.0f, 0.0f, 4.0f), normalize(target - Point3f(0.0f, 0.0f, 4.0f)));
    };
    const int n = 20000;
    WindowEstimate gated = estimateWindow(*scene(true), grid, n, 100 + k, rays);
    WindowEstimate ungated = estimateWindow(*scene(false), grid, n, 200 + k, rays);
    ASSERT_GT(ungated.total.mean(), 0.0) << "the window holds light: the test compares something";
    double se = std::hypot(gated.total.standardError(), ungated.total.standardError());
    EXPECT_NEAR(gated.total.mean(), ungated.total.mean(), 5.0 * se)
        << "gated " << gated.total.mean() << " +- " << gated.total.standardError() << ", ungated "
        << ungated.total.mean() << " +- " << ungated.total.standardError();
  }
}
