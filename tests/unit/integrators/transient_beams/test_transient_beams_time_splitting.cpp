// transient_beams' time_splitting (on by default for transient films): from
// pass 1 on, photons are rouletted and split against the film's time profile
// (a pilot of pass 0's camera samples). The radii are given, so the split and
// the unsplit renders have the same kernels and the same expectation: on a
// fog cube lit from inside (thin and thick, observer time on and off) they
// agree in every bin within their combined noise, with no bias allowance;
// the split one is less noisy in the late bins, which is what it is for; and
// its bits do not depend on the thread count. Photons are drawn
// independently (stratified_photons = false): the late noise compared is
// then the splitting's alone (stratified, the thick cube's late bins read
// the same noise split and unsplit, 0.0209 against 0.0207 over 10 runs). time_gating: a late window's
// render skips (but for before_window_rate of them, weighted) the estimates
// that land wholly before it; gated and ungated agree in every bin and in
// the steady image, which holds the light before the window.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/render/scene.h>

#include "fog_cube_scene.h"
#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

using Cube = FogCube;
const auto& Cubes = FogCubes;

std::shared_ptr<Scene> cubeScene(const Cube& c, bool splitting, bool gating = true, int firstBin = 0) {
  return loadSceneStrict(fogCubeScene(c, str(R"(<integrator type="transient_beams"><integer name="passes" value="3"/>
    <integer name="photon_count" value="1500"/><integer name="max_depth" value="40"/>
    <float name="radius" value="0.04"/><float name="surface_radius" value="0.1"/>
    <float name="surface_time_width" value="0.25"/>
    <boolean name="stratified_photons" value="false"/>
    <boolean name="time_splitting" value=")", splitting ? "true" : "false", R"("/>
    <boolean name="time_gating" value=")", gating ? "true" : "false", R"("/></integrator>)"), 2, firstBin));
}

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
  const int runs = 16;  // the gated steady image is a skewed sum of 8x deposits: enough runs for its spread
  // A nearly clear cube too: there the floor's direct light (next-event
  // estimation, arriving before the window) is most of the steady image.
  for (const Cube& c : {Cubes[0], Cubes[2], Cube{0.01f, 0.5f, true}}) {
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
