// Transient films with pixel filters wider than a pixel (issue 36, item 1):
// Mitsuba users' scenes carry gaussian, tent or Mitchell filters. Tiles carry
// a border as wide as the filter and TransientOutput merges neighbouring
// tiles' borders as they stream. On the fog box (its tiles many: 48x48
// pixels): the steady image of the transient film equals the hdrfilm render
// of the same samples and filter (the same weights, summed in another order),
// the volume's bins plus before and after add up to the steady image, and the
// bits do not depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <femto/image/image_io.h>
#include <femto/render/integrator.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "render_test_util.h"
#include "transient_film_test_util.h"

using namespace femto;

namespace {

constexpr int Resolution = 48;

struct Rendered {
  Bitmap steady, before, after;
  std::vector<float> volume;
  std::string volumeBytes;
};

Rendered renderFog(const std::string& name, const std::string& filter, const std::string& film, int threads,
                   const std::string& integrator = "transient_path", bool completeSteady = false) {
  auto dir = test::scratchDir("pixel-filter-" + name);
  LoadOptions options;
  options.strict = true;
  options.defines = {{"resolution", std::to_string(Resolution)}, {"spp", "4"}, {"rfilter", filter}, {"film", film},
                     {"integrator", integrator}};
  if (film == "transient") {
    options.defines["bins"] = "32";
    options.defines["bin_width"] = "0.25";
    options.defines["frames"] = "false";
    // The steady image with the light after the window too (as hdrfilm's),
    // from samples that do not depend on the window (time gating's and time
    // splitting's do).
    if (completeSteady) {
      options.defines["complete_steady"] = "true";
      options.defines["time_gating"] = "false";
      options.defines["time_splitting"] = "false";
    }
  }
  if (integrator == "transient_beams") {
    options.defines["passes"] = "2";
    options.defines["photon_count"] = "2000";
    options.defines["beam_photon_count"] = "300";
  }
  auto scene = loadScene(std::filesystem::path(FEMTO_SOURCE_DIR) / "scenes/cornell-box-fog/scene.xml", options);
  RenderOptions render;
  render.output = dir / "fog.exr";
  render.progress = false;
  render.seed = 3;
  render.threads = threads;
  RenderStats stats = scene->integrator().render(*scene, render);
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.invalidSamples, 0u);
  Rendered r;
  r.steady = readImage(dir / "fog.exr");
  if (film == "transient") {
    r.before = readImage(dir / "fog_before.exr");
    r.after = readImage(dir / "fog_after.exr");
    int h = 0, w = 0, bins = 0;
    r.volume = test::readVolume(dir / "fog.npy", h, w, bins);
    std::ifstream in(dir / "fog.npy", std::ios::binary);
    r.volumeBytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  return r;
}

double maxRelative(const Bitmap& a, const Bitmap& b) {
  double worst = 0.0, scale = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) scale = std::max(scale, double(std::abs(b.pixel(x, y)[c])));
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c])) / scale);
  return worst;
}

/// Per pixel: the volume's bins plus before plus after (the steady image they must add up to).
Bitmap binsBeforeAndAfter(const Rendered& r) {
  const int bins = 32;
  Bitmap total = r.before;
  for (int y = 0; y < Resolution; ++y)
    for (int x = 0; x < Resolution; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = double(r.before.pixel(x, y)[c]) + double(r.after.pixel(x, y)[c]);
        for (int b = 0; b < bins; ++b) s += r.volume[((size_t(y) * Resolution + x) * bins + b) * 3 + c];
        total.pixel(x, y)[c] = float(s);
      }
  return total;
}

}  // namespace

class TransientPixelFilter : public ::testing::TestWithParam<const char*> {};

TEST_P(TransientPixelFilter, SteadyImageEqualsTheHdrFilmRenderOfTheSameSamples) {
  const std::string filter = GetParam();
  Rendered transient = renderFog(filter + "-transient", filter, "transient", 2, "transient_path", true);
  Rendered steady = renderFog(filter + "-hdrfilm", filter, "hdrfilm", 2);
  const Bitmap& sum = transient.steady;
  EXPECT_LT(maxRelative(sum, steady.steady), 1e-4) << filter;
}

TEST_P(TransientPixelFilter, BinsBeforeAndAfterAddUpToTheSteadyImage) {
  const std::string filter = GetParam();
  Rendered r = renderFog(filter + "-sums", filter, "transient", 2);
  EXPECT_LT(maxRelative(binsBeforeAndAfter(r), r.steady), 1e-4) << filter;
}

TEST_P(TransientPixelFilter, SameBitsForOneAndTwoThreads) {
  const std::string filter = GetParam();
  Rendered one = renderFog(filter + "-t1", filter, "transient", 1);
  Rendered two = renderFog(filter + "-t2", filter, "transient", 2);
  EXPECT_TRUE(one.volumeBytes == two.volumeBytes) << filter;
  EXPECT_EQ(maxRelative(one.steady, two.steady), 0.0) << filter;
}

INSTANTIATE_TEST_SUITE_P(Filters, TransientPixelFilter, ::testing::Values("gaussian", "tent", "mitchell"));

TEST(TransientPixelFilterBeams, PassesWithAGaussianFilterAddUpAndRepeat) {
  // Progressive passes fold each pass's merged tiles: the volume still adds
  // up to the steady image, and the bits do not depend on the thread count.
  Rendered one = renderFog("beams-t1", "gaussian", "transient", 1, "transient_beams");
  Rendered two = renderFog("beams-t2", "gaussian", "transient", 2, "transient_beams");
  EXPECT_TRUE(one.volumeBytes == two.volumeBytes);
  EXPECT_LT(maxRelative(binsBeforeAndAfter(one), one.steady), 1e-4);
}
