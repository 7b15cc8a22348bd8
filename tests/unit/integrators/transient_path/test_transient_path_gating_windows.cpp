// transient_path's time gating (on by default) on generated media scenes:
// a fog cube (thin to thick, eta 1 or 1.33, with or without a scattering
// delay) holding a diffuse floor and a point light, seen from outside with
// observer time on or off. For an early, a middle and a late window the
// gated and the ungated estimators (independent random numbers) agree in
// every bin within their combined noise, and a gated window rendered in two
// halves agrees with it rendered whole (issue 34, part 2).
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/render/scene.h>

#include "plugin_util.h"
#include "transient_test_util.h"
#include "window_estimate.h"

using namespace femto;
using namespace femto::test;

namespace {

struct FogCube {
  float sigmaT = 1.0f, albedo = 0.8f, eta = 1.0f, delay = 0.0f;
  bool observerTime = true;
  Point3f light;

  std::string describe() const {
    return str("sigma_t ", sigmaT, " albedo ", albedo, " eta ", eta, " delay ", delay, " observer time ",
               observerTime ? "on" : "off", " light ", light);
  }
  /// Where the windows start: the earliest arrival at the camera, at most.
  double base() const { return observerTime ? distance(Point3f(0.0f, 0.0f, 4.0f), light) : 0.0; }

  std::shared_ptr<Scene> scene(bool gating) const {
    return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="12"/>
    <boolean name="observer_time" value=")", observerTime ? "true" : "false", R"("/>
    <boolean name="time_gating" value=")", gating ? "true" : "false", R"("/></integrator>
  <medium id="fog" type="homogeneous"><float name="sigma_t" value=")", sigmaT, R"("/>
    <float name="albedo" value=")", albedo, R"("/><float name="eta" value=")", eta, R"("/>
    <phase type="isotropic"><float name="delay" value=")", delay, R"("/></phase></medium>
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.95"/><rotate x="1" angle="-90"/><translate y="-0.95"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.7"/></bsdf>
  </shape>
  <emitter type="point"><point name="position" x=")", light.x, R"(" y=")", light.y, R"(" z=")", light.z,
                               R"("/><float name="intensity" value="3"/></emitter>
  <sensor type="perspective"><transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform></sensor>
</scene>)"));
  }
};

/// Six members: sigma_t log-uniform in [0.2, 5] (0.4 to 10 mean free paths
/// across), albedo 0.5-0.95, eta 1 or 1.33, a delay of 0.3 per scattering
/// event or none, observer time on or off, the light anywhere in the cube.
std::vector<FogCube> generated() {
  PCG32 rng(34, 2);
  std::vector<FogCube> cubes;
  for (int k = 0; k < 6; ++k) {
    FogCube c;
    c.sigmaT = 0.2f * std::pow(25.0f, rng.nextFloat());
    c.albedo = 0.5f + 0.45f * rng.nextFloat();
    c.eta = k % 2 == 0 ? 1.0f : 1.33f;
    c.delay = k % 3 == 2 ? 0.3f : 0.0f;
    c.observerTime = k % 4 != 1;
    c.light = Point3f(1.6f * rng.nextFloat() - 0.8f, 1.6f * rng.nextFloat() - 0.8f, 1.6f * rng.nextFloat() - 0.8f);
    cubes.push_back(c);
  }
  return cubes;
}

Ray cameraRay(PCG32& rng) {
  Point3f target(rng.nextFloat() * 1.6f - 0.8f, rng.nextFloat() * 1.6f - 0.8f, 0.0f);
  return Ray(Point3f(0.0f, 0.0f, 4.0f), normalize(target - Point3f(0.0f, 0.0f, 4.0f)));
}

/// Every bin of `a` within 5 combined standard errors of `b`'s (both
/// estimates independent; the seeds are fixed, so this is deterministic).
void expectBinsAgree(const WindowEstimate& a, const WindowEstimate& b, size_t offset = 0) {
  for (size_t i = 0; i < a.bins.size(); ++i) {
    const Mean& x = a.bins[i];
    const Mean& y = b.bins[i + offset];
    double se = std::hypot(x.standardError(), y.standardError());
    EXPECT_LE(std::abs(x.mean() - y.mean()), 5.0 * se + 1e-12)
        << "bin " << i << ": " << x.mean() << " +- " << x.standardError() << " against " << y.mean() << " +- "
        << y.standardError();
  }
}

}  // namespace

TEST(TransientPathGatingWindows, GatedAgreesWithUngatedPerBinInEarlyMiddleAndLateWindows) {
  const int n = 6000;
  int k = 0;
  for (const FogCube& cube : generated()) {
    SCOPED_TRACE(str("cube ", k, ": ", cube.describe()));
    auto gated = cube.scene(true), ungated = cube.scene(false);
    const double starts[3] = {0.0, 1.2, 3.0};
    const char* names[3] = {"early", "middle", "late"};
    for (int w = 0; w < 3; ++w) {
      SCOPED_TRACE(names[w]);
      TimeGrid grid{cube.base() + starts[w], 0.2, 4};
      WindowEstimate g = estimateWindow(*gated, grid, n, 1000 + 10 * k + w, cameraRay);
      WindowEstimate u = estimateWindow(*ungated, grid, n, 2000 + 10 * k + w, cameraRay);
      ASSERT_GT(u.total.mean(), 0.0) << "the window holds light: the test compares something";
      expectBinsAgree(g, u);
    }
    ++k;
  }
}

TEST(TransientPathGatingWindows, AWindowRenderedInTwoHalvesAgreesWithItWhole) {
  const int n = 6000;
  std::vector<FogCube> cubes = generated();
  for (int k : {0, 3}) {
    const FogCube& cube = cubes[k];
    SCOPED_TRACE(str("cube ", k, ": ", cube.describe()));
    auto scene = cube.scene(true);
    const double start = cube.base() + 0.6;
    WindowEstimate whole = estimateWindow(*scene, TimeGrid{start, 0.2, 8}, n, 3000 + k, cameraRay);
    WindowEstimate first = estimateWindow(*scene, TimeGrid{start, 0.2, 4}, n, 4000 + k, cameraRay);
    WindowEstimate second = estimateWindow(*scene, TimeGrid{start + 0.8, 0.2, 4}, n, 5000 + k, cameraRay);
    ASSERT_GT(second.total.mean(), 0.0);
    expectBinsAgree(first, whole, 0);
    expectBinsAgree(second, whole, 4);
  }
}
