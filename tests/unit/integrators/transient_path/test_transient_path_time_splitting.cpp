// transient_path's time_splitting (on by default for transient films):
// roulette and splitting against the film's time profile, from a pilot of
// camera samples. On a fog cube lit from inside (thin and thick, observer
// time on and off) rendered through the film, the split and the unsplit
// estimators (independent seeds) agree in every bin within their combined
// noise; the split one is less noisy in the late bins, which is what it is
// for; a late window rendered alone agrees with the same bins of the whole
// window; and its bits do not depend on the thread count.
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

std::shared_ptr<Scene> cubeScene(const Cube& c, bool splitting, int firstBin = 0, int bins = 24) {
  return loadSceneStrict(fogCubeScene(c, str(R"(<integrator type="transient_path"><integer name="max_depth" value="40"/>
    <boolean name="time_splitting" value=")", splitting ? "true" : "false", R"("/></integrator>)"), 8, firstBin, bins));
}

}  // namespace

TEST(TransientPathTimeSplitting, AgreesWithMitsubaRoulettePerBinAndIsLessNoisyLate) {
  const int runs = 12;
  for (const Cube& c : Cubes) {
    SCOPED_TRACE(str("sigma_t ", c.sigmaT, " albedo ", c.albedo, " observer time ", c.observerTime));
    std::vector<Mean> split = imageSums(cubeScene(c, true), "time_splitting_on", runs, 100);
    std::vector<Mean> plain = imageSums(cubeScene(c, false), "time_splitting_off", runs, 500);
    ASSERT_GT(plain[plain.size() - 2].mean(), 0.0) << "the last bin holds light: the late bins are compared";
    expectAgree(split, plain, "time_splitting");
    EXPECT_LT(lateNoise(split), lateNoise(plain)) << "splitting spends its paths on the late bins";
  }
}

TEST(TransientPathTimeSplitting, BitsDoNotDependOnTheThreadCount) {
  auto scene = cubeScene(Cubes[1], true);
  auto dir = scratchDir("time_splitting_threads");
  Rendered one = render(scene, dir / "one.exr", 7, 1);
  Rendered two = render(scene, dir / "two.exr", 7, 2);
  Rendered off = render(cubeScene(Cubes[1], false), dir / "off.exr", 7, 2);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(one.volume, two.volume);
  EXPECT_NE(one.volume, off.volume) << "time_splitting changed nothing: the test compares nothing";
}

TEST(TransientPathTimeSplitting, ALateWindowAloneAgreesWithTheWholeWindowsBins) {
  const int runs = 12;
  const Cube& c = Cubes[1];
  std::vector<Mean> whole = imageSums(cubeScene(c, true), "time_splitting_whole", runs, 100);
  std::vector<Mean> late = imageSums(cubeScene(c, true, 16, 8), "time_splitting_late", runs, 500);
  // The bins 16..23 of the whole window; the steady images differ (each holds the light before its own end).
  std::vector<Mean> same(whole.begin() + 16, whole.begin() + 24);
  late.pop_back();
  ASSERT_GT(late.back().mean(), 0.0);
  expectAgree(late, same, "late window");
}
