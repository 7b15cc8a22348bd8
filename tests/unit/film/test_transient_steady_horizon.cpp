// What a transient render's steady image holds (docs/transient-film.md, "What
// the steady image contains"): by default all light arriving before the
// film's horizon (window end + time filter reach), so steady = sum of the bins
// + before + after exactly and, with the box filter, nothing is "after"; with
// complete_steady = true all light, i.e. the steady render of the same samples.
// The film enforces the horizon whatever the integrator reports (an interval
// crossing it keeps its part before it).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"
#include "transient_film_test_util.h"

using namespace femto;

namespace {

constexpr int Resolution = 16, Bins = 32;

struct Render {
  Bitmap steady, before, after;
  std::vector<float> volume;  // empty for a steady film
};

/// scenes/cornell-box-fog over the window [3, 5) (much of its light arrives
/// later), with extra -D `defines`.
Render renderFog(const std::string& name, std::map<std::string, std::string> defines) {
  auto dir = test::scratchDir("steady-horizon-" + name);
  LoadOptions options;
  options.strict = true;
  options.defines = {{"resolution", std::to_string(Resolution)},
                     {"spp", "4"},
                     {"bins", std::to_string(Bins)},
                     {"bin_width", "0.0625"},
                     {"frames", "false"},
                     // Samples that do not depend on the window (time_gating's do), so the
                     // transient and the steady film's renders see the same ones.
                     {"time_gating", "false"},
                     {"time_splitting", "false"}};
  for (auto& [key, value] : defines) options.defines[key] = value;
  // A steady film has no time axis: strict loading refuses -D it would ignore.
  if (auto film = options.defines.find("film"); film != options.defines.end() && film->second == "hdrfilm")
    for (const char* transientOnly : {"bins", "bin_width", "frames"}) options.defines.erase(transientOnly);
  auto scene = loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box-fog/scene.xml", options);
  RenderOptions render;
  render.output = dir / "fog.exr";
  render.progress = false;
  render.seed = 3;
  RenderStats stats = scene->integrator().render(*scene, render);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  Render r{readImage(dir / "fog.exr"), {}, {}, {}};
  if (std::filesystem::exists(dir / "fog.npy")) {
    r.before = readImage(dir / "fog_before.exr");
    r.after = readImage(dir / "fog_after.exr");
    int h = 0, w = 0, bins = 0;
    r.volume = test::readVolume(dir / "fog.npy", h, w, bins);
    EXPECT_EQ(bins, Bins);
  }
  return r;
}

/// Sum over the bins of pixel (x, y), channel c.
double binSum(const Render& r, int x, int y, int c) {
  double sum = 0.0;
  for (int b = 0; b < Bins; ++b) sum += r.volume[((size_t(y) * Resolution + x) * Bins + b) * 3 + c];
  return sum;
}

double imageSum(const Bitmap& image) {
  double sum = 0.0;
  for (int y = 0; y < Resolution; ++y)
    for (int x = 0; x < Resolution; ++x)
      for (int c = 0; c < 3; ++c) sum += image.pixel(x, y)[c];
  return sum;
}

}  // namespace

TEST(TransientSteadyHorizon, SteadyImageHoldsExactlyTheLightBeforeTheHorizon) {
  Render window = renderFog("window", {});
  Render complete = renderFog("complete", {{"complete_steady", "true"}});
  for (int y = 0; y < Resolution; ++y)
    for (int x = 0; x < Resolution; ++x)
      for (int c = 0; c < 3; ++c) {
        float steady = window.steady.pixel(x, y)[c];
        // Box filter: the horizon is the window's end, nothing is deposited after it.
        EXPECT_EQ(window.after.pixel(x, y)[c], 0.0f) << x << "," << y;
        EXPECT_NEAR(steady, binSum(window, x, y, c) + window.before.pixel(x, y)[c], 1e-5 * std::max(1.0f, steady))
            << x << "," << y << "," << c;
        // The bins themselves do not depend on the horizon (same samples).
        for (int b = 0; b < Bins; ++b) {
          size_t i = ((size_t(y) * Resolution + x) * Bins + b) * 3 + c;
          ASSERT_EQ(window.volume[i], complete.volume[i]) << x << "," << y << " bin " << b;
        }
      }
  // The window [3, 5) misses most of the fog's multiple scattering and the
  // walls' indirect light: the complete image holds clearly more.
  double inWindow = imageSum(window.steady), all = imageSum(complete.steady);
  std::printf("steady image sum: window %.4f, complete %.4f, after %.4f\n", inWindow, all, imageSum(complete.after));
  EXPECT_GT(inWindow, 0.0);
  EXPECT_GT(all, 1.2 * inWindow);
}

TEST(TransientSteadyHorizon, CompleteSteadyIsTheSteadyRenderOfTheSameSamples) {
  Render transient = renderFog("complete-transient", {{"complete_steady", "true"}});
  Render steady = renderFog("complete-steady", {{"film", "hdrfilm"}});
  ASSERT_TRUE(steady.volume.empty());
  for (int y = 0; y < Resolution; ++y)
    for (int x = 0; x < Resolution; ++x)
      for (int c = 0; c < 3; ++c) {
        float s = transient.steady.pixel(x, y)[c];
        // Same paths (same seed and sampler streams, infinite horizon in
        // both), summed in another order: float precision.
        EXPECT_NEAR(s, steady.steady.pixel(x, y)[c], 1e-5 * std::max(1.0f, s)) << x << "," << y << "," << c;
        EXPECT_NEAR(s, binSum(transient, x, y, c) + transient.before.pixel(x, y)[c] + transient.after.pixel(x, y)[c],
                    1e-5 * std::max(1.0f, s));
      }
  EXPECT_GT(imageSum(transient.after), 0.0) << "light after the window is in `after`";
}

TEST(TransientSteadyHorizon, FilmDropsWhatArrivesPastTheHorizonAndKeepsThePartOfAnIntervalBeforeIt) {
  // The test ramp integrator reports, for pixel column x, its value spread
  // over OPL [x + 0.5, x + 1.5]; the window is [0, 10) in bins of 1 (box
  // filter), so the horizon is 10: column 9 straddles it, columns >= 10 are past it.
  const int W = 14, H = 2, Bins = 10;
  for (bool complete : {false, true}) {
    SCOPED_TRACE(complete ? "complete_steady" : "default");
    auto dir = test::scratchDir(complete ? "ramp-horizon-complete" : "ramp-horizon");
    Properties film("transient");
    film.setInt("width", W);
    film.setInt("height", H);
    film.setInt("temporal_bins", Bins);
    film.setFloat("bin_width_opl", 1.0f);
    film.setBool("write_frames", false);
    film.setBool("complete_steady", complete);
    Properties ramp("test_transient_ramp");
    ramp.setString("mode", "interval");
    auto scene = test::makeRampScene(film, ramp, 2);
    RenderOptions render;
    render.output = dir / "ramp.exr";
    render.progress = false;
    scene->integrator().render(*scene, render);
    Bitmap steady = readImage(dir / "ramp.exr"), after = readImage(dir / "ramp_after.exr");
    int h = 0, w = 0, bins = 0;
    std::vector<float> volume = test::readVolume(dir / "ramp.npy", h, w, bins);
    const float value = 1.0f;  // the ramp's red channel
    for (int x = 0; x < W; ++x) {
      float binTotal = 0.0f;
      for (int b = 0; b < Bins; ++b) binTotal += volume[(size_t(x) * Bins + b) * 3];
      float inWindow = x < Bins - 1 ? value : (x == Bins - 1 ? 0.5f * value : 0.0f);
      EXPECT_FLOAT_EQ(binTotal, inWindow) << "column " << x;
      EXPECT_FLOAT_EQ(steady.pixel(x, 0)[0], complete ? value : inWindow) << "column " << x;
      EXPECT_FLOAT_EQ(after.pixel(x, 0)[0], complete ? value - inWindow : 0.0f) << "column " << x;
    }
  }
}
