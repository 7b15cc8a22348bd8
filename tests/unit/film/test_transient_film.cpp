// The transient film through the whole pipeline: a synthetic transient
// integrator with a known answer (tests/plugins/test_transient_ramp.cpp puts
// each sample at OPL = its pixel column + offset), rendered with the core's
// streaming loop into .npy, EXR frames and the steady/before/after images.
#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include <femto/image/image_io.h>
#include <femto/film/transient_film.h>
#include <femto/render/transient_integrator.h>

#include "plugin_util.h"
#include "transient_film_test_util.h"

namespace femto {
namespace {

Properties transientFilm(int width, int height, int bins, double start, double binWidth) {
  Properties film("transient");
  film.setInt("width", width);
  film.setInt("height", height);
  film.setInt("temporal_bins", bins);
  film.setFloat("start_opl", start);
  film.setFloat("bin_width_opl", binWidth);
  return film;
}

RenderStats render(const Scene& scene, const std::filesystem::path& out, int threads = 0) {
  RenderOptions options;
  options.output = out;
  options.progress = false;
  options.threads = threads;
  options.seed = 11;
  return scene.integrator().render(scene, options);
}

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

const Color3f RampValue(1.0f, 0.5f, 0.25f);

TEST(TransientFilm, PointSamplesLandInTheExpectedBinsOfVolumeAndFrames) {
  auto dir = test::scratchDir("transient-point");
  const int W = 70, H = 45, Bins = 50;  // partial tiles at the right and bottom; columns >= 50 arrive after the window
  // complete_steady: the film keeps what arrives past the window too (in the
  // steady image and `after`); test_transient_steady_horizon.cpp covers the default.
  Properties film = transientFilm(W, H, Bins, 0.0, 1.0);
  film.setBool("complete_steady", true);
  film.setBool("write_frames", true);  // off by default (FramesAreOffByDefault)
  auto scene = test::makeRampScene(film, Properties("test_transient_ramp"), 3);
  RenderStats stats = render(*scene, dir / "out.exr");
  EXPECT_TRUE(stats.completed);
  EXPECT_EQ(stats.samples, uint64_t(W * H * 3));

  int h, w, bins;
  std::vector<float> volume = test::readVolume(dir / "out.npy", h, w, bins);
  ASSERT_EQ(h, H);
  ASSERT_EQ(w, W);
  ASSERT_EQ(bins, Bins);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int b = 0; b < Bins; ++b) {
        const float* v = &volume[((size_t(y) * W + x) * Bins + b) * 3];
        float expected = b == x ? 1.0f : 0.0f;
        ASSERT_EQ(v[0], expected * RampValue.r) << x << "," << y << " bin " << b;
        ASSERT_EQ(v[1], expected * RampValue.g);
        ASSERT_EQ(v[2], expected * RampValue.b);
      }
  Bitmap steady = readImage(dir / "out.exr"), before = readImage(dir / "out_before.exr"),
         after = readImage(dir / "out_after.exr");
  ASSERT_EQ(steady.width, W);
  EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      EXPECT_EQ(steady.pixel(x, y)[1], RampValue.g);  // every contribution, in the window or not
      EXPECT_EQ(before.pixel(x, y)[1], 0.0f);
      EXPECT_EQ(after.pixel(x, y)[1], x >= Bins ? RampValue.g : 0.0f);
    }
  // One EXR per bin; frame b lights column b only.
  size_t frames = std::distance(std::filesystem::directory_iterator(dir / "out_frames"), {});
  EXPECT_EQ(frames, size_t(Bins));
  for (int b : {0, 7, Bins - 1}) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%05d.exr", b);
    Bitmap frame = readImage(dir / "out_frames" / name);
    ASSERT_EQ(frame.width, W);
    ASSERT_EQ(frame.height, H);
    for (int y = 0; y < H; y += 11)
      for (int x = 0; x < W; ++x) EXPECT_EQ(frame.pixel(x, y)[0], x == b ? RampValue.r : 0.0f) << name << " " << x;
  }
  std::filesystem::remove_all(dir);
}

TEST(TransientFilm, NpyHeaderIsNumpyVersion1WithAlignedData) {
  std::vector<char> header = npyHeader({45, 70, 50, 3});
  std::string text(header.begin(), header.end());
  EXPECT_EQ(text.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  EXPECT_EQ(header.size() % 64, 0u);
  EXPECT_EQ(size_t(uint8_t(header[8])) + 256 * uint8_t(header[9]), header.size() - 10);
  EXPECT_NE(text.find("{'descr': '<f4', 'fortran_order': False, 'shape': (45, 70, 50, 3, ), }"), std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

TEST(TransientFilm, FramesAreOffByDefault) {
  // Per-bin EXR frames cost a fixed ~0.5-1 s per 400-bin render; `femto frames`
  // makes them on demand, write_frames=true at render time.
  auto dir = test::scratchDir("transient-noframes");
  auto scene = test::makeRampScene(transientFilm(8, 4, 6, 0.0, 1.0), Properties("test_transient_ramp"), 1);
  render(*scene, dir / "out.exr");
  EXPECT_TRUE(std::filesystem::exists(dir / "out.npy"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out_frames"));
  std::filesystem::remove_all(dir);
}

TEST(TransientFilm, SumOverBinsEqualsSteadyRestrictedToTheWindow) {
  // Random-length intervals (jitter) spread by a gaussian time filter over a
  // window that cuts columns at both ends: before, inside and after all occur.
  auto dir = test::scratchDir("transient-sum");
  const int W = 40, H = 6, Bins = 24;
  Properties film = transientFilm(W, H, Bins, 6.0, 1.25);
  film.setString("time_filter", "gaussian");
  film.setFloat("time_filter_width", 0.8);
  film.setBool("write_frames", false);
  film.setBool("complete_steady", true);  // every column's whole value in the steady image
  Properties ramp("test_transient_ramp");
  ramp.setString("mode", "interval");
  ramp.setFloat("length", 3.0);
  ramp.setFloat("jitter", 2.0);
  auto scene = test::makeRampScene(film, ramp, 4);
  render(*scene, dir / "out.exr");
  int h, w, bins;
  std::vector<float> volume = test::readVolume(dir / "out.npy", h, w, bins);
  Bitmap steady = readImage(dir / "out.exr"), before = readImage(dir / "out_before.exr"),
         after = readImage(dir / "out_after.exr");
  EXPECT_FALSE(std::filesystem::exists(dir / "out_frames"));
  int sawBefore = 0, sawAfter = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int b = 0; b < Bins; ++b) sum += volume[((size_t(y) * W + x) * Bins + b) * 3 + c];
        double window = double(steady.pixel(x, y)[c]) - before.pixel(x, y)[c] - after.pixel(x, y)[c];
        EXPECT_NEAR(sum, window, 1e-6 * steady.pixel(x, y)[c]) << x << "," << y;
        EXPECT_EQ(steady.pixel(x, y)[c], RampValue[c]);
        sawBefore += before.pixel(x, y)[c] > 0.0f, sawAfter += after.pixel(x, y)[c] > 0.0f;
      }
  EXPECT_GT(sawBefore, 0);
  EXPECT_GT(sawAfter, 0);
  std::filesystem::remove_all(dir);
}

TEST(TransientFilm, VolumeAndSteadyAreBitwiseIdenticalForOneAndTwoThreads) {
  auto dir = test::scratchDir("transient-determinism");
  Properties film = transientFilm(70, 40, 30, 0.0, 2.5);
  film.setString("time_filter", "tent");
  film.setBool("write_frames", true);
  Properties ramp("test_transient_ramp");
  ramp.setFloat("jitter", 5.0);
  auto scene = test::makeRampScene(film, ramp, 5);
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
    render(*scene, dir / "one.exr");
  }
  render(*scene, dir / "two.exr", 2);
  std::string one = fileBytes(dir / "one.npy"), two = fileBytes(dir / "two.npy");
  ASSERT_GT(one.size(), size_t(70 * 40 * 30 * 12));
  EXPECT_TRUE(one == two);
  EXPECT_TRUE(readImage(dir / "one.exr").data == readImage(dir / "two.exr").data);
  EXPECT_TRUE(fileBytes(dir / "one_frames/frame_00013.exr") == fileBytes(dir / "two_frames/frame_00013.exr"));
  std::filesystem::remove_all(dir);
}

TEST(TransientFilm, CropWindowGivesTheCropShapeAndColumns) {
  auto dir = test::scratchDir("transient-crop");
  Properties film = transientFilm(64, 32, 64, 0.0, 1.0);
  film.setInt("crop_offset_x", 10);
  film.setInt("crop_offset_y", 3);
  film.setInt("crop_width", 20);
  film.setInt("crop_height", 5);
  film.setBool("write_frames", false);
  auto scene = test::makeRampScene(film, Properties("test_transient_ramp"), 1);
  render(*scene, dir / "out.exr");
  int h, w, bins;
  std::vector<float> volume = test::readVolume(dir / "out.npy", h, w, bins);
  ASSERT_EQ(h, 5);
  ASSERT_EQ(w, 20);
  for (int x = 0; x < 20; ++x) EXPECT_EQ(volume[(size_t(x) * bins + (x + 10)) * 3], RampValue.r) << x;
  std::filesystem::remove_all(dir);
}

TEST(TransientFilm, SecondsAreConvertedToOpticalPathLengthInMetres) {
  Properties film("transient");
  film.setInt("temporal_bins", 10);
  film.setFloat("start_time", 1e-9);
  film.setFloat("bin_width_time", 2e-11);
  auto f = test::createPlugin<TransientFilm>(ObjectKind::Film, film);
  EXPECT_NEAR(f->timeGrid().start, 0.299792458, 1e-7);
  EXPECT_NEAR(f->timeGrid().binWidth, 0.00599584916, 1e-9);
  // mitransient's name builds the same film.
  Properties mitransient = transientFilm(8, 8, 4, 1.0, 0.5);
  mitransient.setPluginName("transient_hdr_film");
  auto g = test::createPlugin<TransientFilm>(ObjectKind::Film, mitransient);
  EXPECT_EQ(g->timeGrid().end(), 3.0);
}

TEST(TransientFilm, BadParametersAreClearErrors) {
  auto build = [](const Properties& props) { return [props] { test::makeTestPlugin(ObjectKind::Film, props); }; };
  Properties both = transientFilm(8, 8, 4, 0.0, 1.0);
  both.setFloat("bin_width_time", 1e-9);
  EXPECT_NE(test::errorMessageOf(build(both)).find("either in optical path length"), std::string::npos);
  Properties none("transient");
  none.setInt("temporal_bins", 4);
  EXPECT_NE(test::errorMessageOf(build(none)).find("bin_width_opl"), std::string::npos);
  Properties zero = transientFilm(8, 8, 0, 0.0, 1.0);
  EXPECT_NE(test::errorMessageOf(build(zero)).find("temporal_bins"), std::string::npos);
  Properties negative = transientFilm(8, 8, 4, 0.0, -1.0);
  EXPECT_NE(test::errorMessageOf(build(negative)).find("must be positive"), std::string::npos);
  Properties filter = transientFilm(8, 8, 4, 0.0, 1.0);
  filter.setString("time_filter", "lanczos");
  EXPECT_NE(test::errorMessageOf(build(filter)).find("\"box\", \"tent\" or \"gaussian\""), std::string::npos);
}

TEST(TransientFilm, SteadyIntegratorIsRefusedBeforeRendering) {
  Properties path("path");
  auto scene = test::makeRampScene(transientFilm(8, 8, 4, 0.0, 1.0), path, 1);
  std::string message = test::errorMessageOf([&] { render(*scene, {}); });
  EXPECT_NE(message.find("transient film needs a transient integrator"), std::string::npos) << message;
}

TEST(TransientFilm, TransientIntegratorOnASteadyFilmSumsAllContributions) {
  auto dir = test::scratchDir("transient-steady");
  Properties film("hdrfilm");
  film.setInt("width", 33);
  film.setInt("height", 7);
  film.setObject("rfilter", test::makeTestPlugin(ObjectKind::ReconstructionFilter, Properties("box")));
  Properties ramp("test_transient_ramp");
  ramp.setString("mode", "interval");
  ramp.setFloat("offset", 1e6);  // far outside any window: a steady film does not care
  auto scene = test::makeRampScene(film, ramp, 2);
  render(*scene, dir / "out.exr");
  Bitmap image = readImage(dir / "out.exr");
  ASSERT_EQ(image.width, 33);
  for (float v : image.data) ASSERT_TRUE(v == RampValue.r || v == RampValue.g || v == RampValue.b);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace femto
