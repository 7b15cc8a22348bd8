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

#include "transient_agreement_util.h"

using namespace femto;
using namespace femto::test;

namespace {

struct Cube {
  float sigmaT, albedo;
  bool observerTime;
};

std::shared_ptr<Scene> cubeScene(const Cube& c, bool splitting, int firstBin = 0, int bins = 24) {
  return loadSceneStrict(str(R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="40"/>
    <boolean name="observer_time" value=")", c.observerTime ? "true" : "false", R"("/>
    <boolean name="time_splitting" value=")", splitting ? "true" : "false", R"("/></integrator>
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
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler>
    <film type="transient"><integer name="width" value="12"/><integer name="height" value="12"/>
      <integer name="temporal_bins" value=")", bins, R"("/><float name="start_opl" value=")",
                             (c.observerTime ? 3.0 : 0.0) + 0.25 * firstBin, R"("/><float name="bin_width_opl" value="0.25"/><rfilter type="box"/></film>
  </sensor>
</scene>)"));
}

/// Per time bin and then for the steady image, the image sum (channel
/// average) over `runs` renders with seeds seed0, seed0 + 1, ...
std::vector<Mean> binSums(const std::shared_ptr<Scene>& scene, const std::string& name, uint64_t seed0, int runs) {
  auto dir = scratchDir(name);
  std::vector<Mean> sums;
  for (int run = 0; run < runs; ++run) {
    Rendered r = render(scene, dir / "out.exr", seed0 + uint64_t(run));
    std::vector<double> perBin(size_t(r.bins) + 1, 0.0);  // the bins, then the steady image
    for (size_t i = 0; i < r.volume.size(); ++i) perBin[(i / 3) % size_t(r.bins)] += r.volume[i] / 3.0;
    for (int y = 0; y < r.steady.height; ++y)
      for (int x = 0; x < r.steady.width; ++x)
        for (int c = 0; c < 3; ++c) perBin.back() += r.steady.pixel(x, y)[c] / 3.0;
    sums.resize(perBin.size());
    for (size_t b = 0; b < perBin.size(); ++b) sums[b].add(perBin[b]);
  }
  std::filesystem::remove_all(dir);
  return sums;
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

TEST(TransientPathTimeSplitting, AgreesWithMitsubaRoulettePerBinAndIsLessNoisyLate) {
  const int runs = 12;
  for (const Cube& c : Cubes) {
    SCOPED_TRACE(str("sigma_t ", c.sigmaT, " albedo ", c.albedo, " observer time ", c.observerTime));
    std::vector<Mean> split = binSums(cubeScene(c, true), "time_splitting_on", 100, runs);
    std::vector<Mean> plain = binSums(cubeScene(c, false), "time_splitting_off", 500, runs);
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
  std::vector<Mean> whole = binSums(cubeScene(c, true), "time_splitting_whole", 100, runs);
  std::vector<Mean> late = binSums(cubeScene(c, true, 16, 8), "time_splitting_late", 500, runs);
  // The bins 16..23 of the whole window; the steady images differ (each holds the light before its own end).
  std::vector<Mean> same(whole.begin() + 16, whole.begin() + 24);
  late.pop_back();
  ASSERT_GT(late.back().mean(), 0.0);
  expectAgree(late, same, "late window");
}
