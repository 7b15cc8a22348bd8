// transient_beams' time_splitting (on by default for transient films): from
// pass 1 on, photons are rouletted and split against the film's time profile
// (a pilot of pass 0's camera samples). The radii are given, so the split and
// the unsplit renders have the same kernels and the same expectation: on a
// fog cube lit from inside (thin and thick, observer time on and off) they
// agree in every bin within their combined noise, with no bias allowance;
// the split one is less noisy in the late bins, which is what it is for; and
// its bits do not depend on the thread count. time_gating: a late window's
// render skips (but for before_window_rate of them, weighted) the estimates
// that land wholly before it; gated and ungated agree in every bin and in
// the steady image, which holds the light before the window.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/render/scene.h>

#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

struct Cube {
  float sigmaT, albedo;
  bool observerTime;
};

std::shared_ptr<Scene> cubeScene(const Cube& c, bool splitting, bool gating = true, int firstBin = 0) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_beams"><integer name="passes" value="3"/>
    <integer name="photon_count" value="1500"/><integer name="max_depth" value="40"/>
    <float name="radius" value="0.04"/><float name="surface_radius" value="0.1"/>
    <float name="surface_time_width" value="0.25"/>
    <boolean name="observer_time" value=")", c.observerTime ? "true" : "false", R"("/>
    <boolean name="time_splitting" value=")", splitting ? "true" : "false", R"("/>
    <boolean name="time_gating" value=")", gating ? "true" : "false", R"("/></integrator>
  <medium id="fog" type="homogeneous"><float name="sigma_t" value=")", c.sigmaT, R"("/>
    <float name="albedo" value=")", c.albedo, R"("/></medium>
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="0.95"/><rotate x="1" angle="-90"/><translate y="-0.95"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.7"/></bsdf>
  </shape>
  <emitter type="point"><point name="position" x="0.2" y="0.3" z="-0.1"/><float name="intensity" value="3"/></emitter>
  <sensor type="perspective"><float name="fov" value="35"/>
    <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="2"/></sampler>
    <film type="transient"><integer name="width" value="12"/><integer name="height" value="12"/>
      <integer name="temporal_bins" value="24"/><float name="start_opl" value=")",
                             (c.observerTime ? 3.0 : 0.0) + 0.25 * firstBin, R"("/><float name="bin_width_opl" value="0.25"/><rfilter type="box"/></film>
  </sensor>
</scene>)"));
}

/// The late half of the bins' summed squared relative standard error.
double lateNoise(const std::vector<Mean>& sums) {
  double n = 0.0;
  for (size_t b = (sums.size() - 1) / 2; b + 1 < sums.size(); ++b)
    n += std::pow(sums[b].standardError() / std::max(sums[b].mean(), 1e-12), 2.0);
  return n;
}

const Cube Cubes[] = {{0.5f, 0.8f, true}, {3.0f, 0.95f, true}, {3.0f, 0.95f, false}};

}  // namespace

TEST(TransientBeamsTimeSplitting, AgreesWithoutSplittingPerBinAndIsLessNoisyLate) {
  const int runs = 10;
  for (const Cube& c : Cubes) {
    SCOPED_TRACE(str("sigma_t ", c.sigmaT, " albedo ", c.albedo, " observer time ", c.observerTime));
    std::vector<Mean> split = imageSums(cubeScene(c, true), "beams_time_splitting_on", runs, 100);
    std::vector<Mean> plain = imageSums(cubeScene(c, false), "beams_time_splitting_off", runs, 500);
    ASSERT_GT(plain[plain.size() - 2].mean(), 0.0) << "the last bin holds light: the late bins are compared";
    expectAgree(split, plain, "time_splitting");
    EXPECT_LT(lateNoise(split), lateNoise(plain)) << "splitting spends its photons on the late bins";
  }
}

TEST(TransientBeamsTimeSplitting, BitsDoNotDependOnTheThreadCount) {
  auto scene = cubeScene(Cubes[1], true);
  auto dir = scratchDir("beams_time_splitting_threads");
  Rendered one = render(scene, dir / "one.exr", 3, 1), two = render(scene, dir / "two.exr", 3, 2);
  ASSERT_EQ(one.volume.size(), two.volume.size());
  size_t differing = 0;
  for (size_t i = 0; i < one.volume.size(); ++i) differing += one.volume[i] != two.volume[i];
  EXPECT_EQ(differing, 0u);
}

TEST(TransientBeamsTimeGating, ALateWindowAgreesWithoutGatingPerBinAndInTheSteadyImage) {
  // The window starts 12 bins in: half the light arrives before it.
  const int runs = 10;
  for (const Cube& c : {Cubes[0], Cubes[2]}) {
    SCOPED_TRACE(str("sigma_t ", c.sigmaT, " albedo ", c.albedo, " observer time ", c.observerTime));
    std::vector<Mean> gated = imageSums(cubeScene(c, true, true, 12), "beams_time_gating_on", runs, 100);
    std::vector<Mean> plain = imageSums(cubeScene(c, true, false, 12), "beams_time_gating_off", runs, 500);
    ASSERT_GT(plain.back().mean(), 1.5 * [&] {
      double window = 0.0;
      for (size_t b = 0; b + 1 < plain.size(); ++b) window += plain[b].mean();
      return window;
    }()) << "the steady image holds light from before the window: its weight is tested";
    expectAgree(gated, plain, "time_gating");
  }
}
