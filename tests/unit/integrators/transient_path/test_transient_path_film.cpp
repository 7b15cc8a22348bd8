// transient_path end to end through the transient film: the time integral of
// the streamed volume is the steady image of the same render (same samples),
// and it agrees with an independent steady render of the same scene.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"
#include "transient_film_test_util.h"

using namespace femto;

namespace {

/// A small foggy room: floor, sphere light, homogeneous medium in a cube
/// boundary without a BSDF (index-matched), camera outside. With max_depth 6
/// no path is longer than ~60 scene units, so a window of 128 units holds every
/// contribution and nothing arrives after it.
std::string foggyScene(const std::string& film, int spp) {
  return R"(<scene version="3.0.0">
  <integrator type="transient_path"><integer name="max_depth" value="6"/></integrator>
  <medium type="homogeneous" id="fog">
    <rgb name="sigma_t" value="0.3"/><rgb name="albedo" value="0.8"/>
  </medium>
  <shape type="cube">
    <transform name="to_world"><scale value="2"/></transform>
    <ref name="interior" id="fog"/>
  </shape>
  <shape type="rectangle">
    <transform name="to_world"><scale value="1.9"/><rotate x="1" angle="-90"/><translate y="-1"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.5, 0.7"/></bsdf>
  </shape>
  <shape type="sphere">
    <point name="center" x="0.3" y="0.6" z="0"/><float name="radius" value="0.3"/>
    <emitter type="area"><rgb name="radiance" value="6"/></emitter>
  </shape>
  <sensor type="perspective">
    <float name="fov" value="50"/>
    <transform name="to_world"><lookat origin="0, 0, 4.5" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value=")" +
         std::to_string(spp) + R"("/></sampler>
    )" + film + R"(
  </sensor>
</scene>)";
}

const char* TransientFilmElement = R"(<film type="transient">
      <integer name="width" value="20"/><integer name="height" value="20"/>
      <integer name="temporal_bins" value="128"/>
      <float name="start_opl" value="0"/><float name="bin_width_opl" value="1"/>
      <rfilter type="box"/>
    </film>)";
const char* SteadyFilm = R"(<film type="hdrfilm">
      <integer name="width" value="20"/><integer name="height" value="20"/>
      <rfilter type="box"/>
    </film>)";

Bitmap renderTo(const std::string& xml, const std::filesystem::path& out, uint64_t seed) {
  LoadOptions options;
  options.strict = true;
  auto scene = loadSceneFromString(xml, FEMTO_SOURCE_DIR, options, "foggy.xml");
  RenderOptions render;
  render.output = out;
  render.seed = seed;
  render.progress = false;
  RenderStats stats = scene->integrator().render(*scene, render);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  return readImage(out);
}

}  // namespace

TEST(TransientPathFilm, TimeIntegralOfTheVolumeIsTheSteadyImageOfTheSameSamples) {
  auto dir = test::scratchDir("transient-path-film");
  Bitmap steady = renderTo(foggyScene(TransientFilmElement, 8), dir / "fog.exr", 1);
  Bitmap after = readImage(dir / "fog_after.exr");
  Bitmap before = readImage(dir / "fog_before.exr");
  int h = 0, w = 0, bins = 0;
  std::vector<float> volume = test::readVolume(dir / "fog.npy", h, w, bins);
  ASSERT_EQ(h, 20);
  ASSERT_EQ(w, 20);
  ASSERT_EQ(bins, 128);
  double total = 0.0;
  int busyBins = 0;
  std::vector<double> perBin(bins, 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int b = 0; b < bins; ++b) {
          float v = volume[((size_t(y) * w + x) * bins + b) * 3 + c];
          sum += v;
          perBin[b] += v;
        }
        float s = steady.pixel(x, y)[c];
        EXPECT_EQ(after.pixel(x, y)[c], 0.0f) << "nothing may arrive after OPL 128 with max_depth 6";
        EXPECT_EQ(before.pixel(x, y)[c], 0.0f);
        // Same samples, summed in another order: float precision.
        EXPECT_NEAR(sum, s, 1e-5 * std::max(1.0f, std::abs(s))) << x << "," << y << "," << c;
        total += s;
      }
  for (double v : perBin) busyBins += v > 0.0;
  EXPECT_GT(total, 0.0);
  // Light is spread over time (direct, fog, floor bounces), not in one bin.
  EXPECT_GT(busyBins, 8);
}

TEST(TransientPathFilm, TimeIntegralAgreesWithAnIndependentSteadyRender) {
  auto dir = test::scratchDir("transient-path-vs-steady");
  // 1024 spp over 400 pixels puts the standard error of the mean difference
  // near 1 % of the image level (heavy-tailed: fog paths that find the small
  // light), so 5 sigma catches a bias above ~6 % (checked: a 10 % error fails).
  Bitmap transientSteady = renderTo(foggyScene(TransientFilmElement, 1024), dir / "t.exr", 7);
  Bitmap steady = renderTo(foggyScene(SteadyFilm, 1024), dir / "s.exr", 12345);
  // Per-pixel differences of two independent unbiased estimates have mean 0;
  // test the mean difference against its standard error (5 sigma).
  for (int c = 0; c < 3; ++c) {
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int y = 0; y < 20; ++y)
      for (int x = 0; x < 20; ++x) {
        double d = double(transientSteady.pixel(x, y)[c]) - steady.pixel(x, y)[c];
        sum += d;
        sum2 += d * d;
        ++n;
      }
    double mean = sum / n;
    double stderrMean = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / (n - 1));
    double level = 0.0;
    for (int y = 0; y < 20; ++y)
      for (int x = 0; x < 20; ++x) level += steady.pixel(x, y)[c] / double(n);
    std::printf("channel %d: mean level %.5f, mean difference %.3g, standard error %.3g\n", c, level, mean, stderrMean);
    EXPECT_LT(std::abs(mean), 5.0 * stderrMean + 1e-7) << "channel " << c;
  }
}

TEST(TransientPathFilm, ShippedFogCornellBoxLoadsStrictlyAndShowsTheWavefront) {
  auto dir = test::scratchDir("fog-cornell-box");
  LoadOptions options;
  options.strict = true;
  options.defines = {{"resolution", "16"}, {"spp", "4"}, {"bins", "64"}, {"bin_width", "0.16"}};
  auto scene = loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box-fog/scene.xml", options);
  RenderOptions render;
  render.output = dir / "fog.exr";
  render.progress = false;
  RenderStats stats = scene->integrator().render(*scene, render);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  int h = 0, w = 0, bins = 0;
  std::vector<float> volume = test::readVolume(dir / "fog.npy", h, w, bins);
  ASSERT_EQ(bins, 64);
  // No light path is shorter than the straight line from the light (0, 0.8, 0)
  // to the camera (0, 0, 3.9): |light - camera| = 3.981. Bins 0-5 cover OPL
  // [3, 3.96) and must be exactly empty; the wavefront arrives in bin 6.
  std::vector<double> perBin(bins, 0.0);
  for (size_t i = 0; i < volume.size(); ++i) perBin[(i / 3) % bins] += volume[i];
  for (int b = 0; b < 6; ++b) EXPECT_EQ(perBin[b], 0.0) << "bin " << b;
  EXPECT_GT(perBin[6] + perBin[7] + perBin[8], 0.0) << "the direct wavefront through the fog";
  double total = 0.0;
  for (double v : perBin) total += v;
  EXPECT_GT(total, 0.0);
}
