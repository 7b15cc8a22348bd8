// A long time window can be rendered in pieces: rendering the window [a, b)
// and then [b, c) with the same seed gives exactly the bins of one render of
// [a, c). Why it is exact (docs/transient-film.md, "Splitting a render"):
// transient_path stops a path only once its OPL passes the horizon, and every
// later contribution of a path is later still, so what lands before b is
// computed from the same random numbers in both renders, provided a sample's
// random numbers do not depend on how many the samples before it used (the
// independent sampler seeds each sample's own stream). With bin edges on
// dyadic OPLs the bin of a contribution is computed exactly in both renders,
// so the bins are bitwise equal, for the box and the tent time filter alike
// (the tent's horizon reaches one bin past the window on both sides).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"
#include "transient_film_test_util.h"

using namespace femto;

namespace {

constexpr int Resolution = 20;
// Bin width 1/16 and window edges 3, 5, 7: every bin edge is a dyadic
// rational, so (opl - start) / bin width is exact in both renders.
constexpr double BinWidth = 0.0625;

/// The volume (h, w, bins, 3) of scenes/cornell-box-fog rendered over
/// [start, start + bins * BinWidth) with `filter`.
std::vector<float> renderWindow(const std::string& name, double start, int bins, const std::string& filter) {
  auto dir = test::scratchDir("time-window-" + name);
  LoadOptions options;
  options.strict = true;
  options.defines = {{"resolution", std::to_string(Resolution)}, {"spp", "4"},
                     {"bins", std::to_string(bins)},           {"bin_width", "0.0625"},
                     {"start", std::to_string(start)},         {"time_filter", filter},
                     {"frames", "false"},                   {"time_gating", "false"},
                     {"time_splitting", "false"}};
  // time_gating and time_splitting (on by default) sample for the window by design: equal within noise only.
  auto scene = loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box-fog/scene.xml", options);
  RenderOptions render;
  render.output = dir / "fog.exr";
  render.progress = false;
  render.seed = 11;
  RenderStats stats = scene->integrator().render(*scene, render);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  int h = 0, w = 0, readBins = 0;
  std::vector<float> volume = test::readVolume(dir / "fog.npy", h, w, readBins);
  EXPECT_EQ(readBins, bins);
  return volume;
}

void expectSplitEqualsWhole(const std::string& filter) {
  constexpr int Half = 32;
  std::vector<float> first = renderWindow(filter + "-first", 3.0, Half, filter);
  std::vector<float> second = renderWindow(filter + "-second", 3.0 + Half * BinWidth, Half, filter);
  std::vector<float> whole = renderWindow(filter + "-whole", 3.0, 2 * Half, filter);
  ASSERT_EQ(whole.size(), 2 * first.size());
  ASSERT_EQ(whole.size(), 2 * second.size());
  size_t mismatches = 0, nonzero[2] = {0, 0};
  for (size_t pixel = 0; pixel < size_t(Resolution) * Resolution; ++pixel)
    for (int b = 0; b < 2 * Half; ++b)
      for (int c = 0; c < 3; ++c) {
        const std::vector<float>& part = b < Half ? first : second;
        float split = part[(pixel * Half + b % Half) * 3 + c];
        float one = whole[(pixel * 2 * Half + b) * 3 + c];
        if (split != one && ++mismatches <= 5)
          ADD_FAILURE() << "pixel " << pixel << " bin " << b << " channel " << c << ": split " << split
                        << ", whole " << one;
        nonzero[b / Half] += one > 0.0f;
      }
  EXPECT_EQ(mismatches, 0u);
  // Both halves hold light (the fog's wavefront and the walls): the test compares something.
  EXPECT_GT(nonzero[0], 1000u);
  EXPECT_GT(nonzero[1], 1000u);
}

}  // namespace

TEST(TransientTimeWindowSplit, TwoWindowsGiveTheBinsOfOneRenderExactlyWithTheBoxFilter) {
  expectSplitEqualsWhole("box");
}

TEST(TransientTimeWindowSplit, TwoWindowsGiveTheBinsOfOneRenderExactlyWithTheTentFilter) {
  expectSplitEqualsWhole("tent");
}
