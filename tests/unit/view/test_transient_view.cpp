// The viewing tools' core (src/core/femto/view): bounded-memory reads of a
// transient volume, exposure percentiles, streak slices, the running
// integral, false colour; on tiny synthetic volumes written by the test.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include <femto/base/error.h>
#include <femto/film/npy_volume.h>
#include <femto/view/contact_sheet.h>
#include <femto/view/display.h>
#include <femto/view/exposure.h>
#include <femto/view/running_integral.h>
#include <femto/view/streak.h>
#include <femto/film/volume_scan.h>

namespace fs = std::filesystem;

namespace femto {
namespace {

constexpr int H = 5, W = 7, Bins = 9;
constexpr int HotY = 3, HotX = 2, HotBin = 6;
constexpr float Hot[3] = {4.0f, 2.0f, 1.0f};

fs::path testDir() {
  fs::path dir = fs::path(::testing::TempDir()) / ("femto_view_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

/// A black H x W x Bins volume with one hot voxel.
fs::path writeHotVoxelVolume(const std::string& name) {
  fs::path path = testDir() / name;
  NpyVolume volume = NpyVolume::create(path, H, W, Bins);
  std::vector<float> pixel(size_t(Bins) * 3, 0.0f);
  std::copy_n(Hot, 3, &pixel[size_t(HotBin) * 3]);
  volume.writePixels(HotY, HotX, 1, pixel.data());
  return path;
}

/// Random non-negative values everywhere; returned as well, in file layout.
std::vector<float> writeRandomVolume(const fs::path& path, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> data(size_t(H) * W * Bins * 3);
  for (float& v : data) v = u(rng) < 0.3f ? 0.0f : u(rng);
  NpyVolume volume = NpyVolume::create(path, H, W, Bins);
  for (int y = 0; y < H; ++y) volume.writePixels(y, 0, W, &data[size_t(y) * W * Bins * 3]);
  return data;
}

TEST(TransientView, HotVoxelLandsInItsFrameAndPixelOnly) {
  const NpyVolume volume = NpyVolume::open(writeHotVoxelVolume("hot_frames.npy"));
  // Read in two batches that split the range, as the frames command does.
  for (int split : {1, HotBin, HotBin + 1}) {
    std::vector<Bitmap> frames = readFrames(volume, 0, split);
    std::vector<Bitmap> rest = readFrames(volume, split, Bins - split);
    frames.insert(frames.end(), rest.begin(), rest.end());
    ASSERT_EQ(frames.size(), size_t(Bins));
    for (int b = 0; b < Bins; ++b) {
      ASSERT_EQ(frames[size_t(b)].width, W);
      ASSERT_EQ(frames[size_t(b)].height, H);
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
          for (int c = 0; c < 3; ++c) {
            const bool hot = b == HotBin && x == HotX && y == HotY;
            EXPECT_EQ(frames[size_t(b)].pixel(x, y)[c], hot ? Hot[c] : 0.0f) << b << ' ' << x << ' ' << y;
          }
    }
  }
  EXPECT_THROW(readFrames(volume, 5, Bins), Error);
}

TEST(TransientView, StreakHasWidthByBinsWithHotValueAtXAndBin) {
  const NpyVolume volume = NpyVolume::open(writeHotVoxelVolume("hot_streak.npy"));
  const Bitmap streak = streakImage(volume, HotY);
  ASSERT_EQ(streak.width, W);
  ASSERT_EQ(streak.height, Bins);
  for (int b = 0; b < Bins; ++b)
    for (int x = 0; x < W; ++x)
      EXPECT_EQ(streak.pixel(x, b)[0], x == HotX && b == HotBin ? Hot[0] : 0.0f) << x << ' ' << b;
  const Bitmap other = streakImage(volume, HotY - 1);
  for (float v : other.data) EXPECT_EQ(v, 0.0f);
  EXPECT_THROW(streakImage(volume, H), Error);
  EXPECT_THROW(streakImage(volume, -1), Error);
}

TEST(TransientView, RunningIntegralIsTheCumulativeSumOverBins) {
  const fs::path in = testDir() / "random.npy", out = testDir() / "random_integral.npy";
  const std::vector<float> data = writeRandomVolume(in, 7);
  const NpyVolume volume = NpyVolume::open(in);
  writeRunningIntegral(volume, in, out);
  const NpyVolume integral = NpyVolume::open(out);
  ASSERT_EQ(integral.height(), H);
  ASSERT_EQ(integral.width(), W);
  ASSERT_EQ(integral.bins(), Bins);
  std::vector<float> pixel(size_t(Bins) * 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      integral.readPixels(y, x, 1, pixel.data());
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int b = 0; b < Bins; ++b) {
          sum += data[((size_t(y) * W + x) * Bins + b) * 3 + c];
          EXPECT_NEAR(pixel[size_t(b) * 3 + c], sum, 1e-6 * (1 + sum));
        }
      }
    }
  // The frame-by-frame running sum (what `femto frames --running-integral`
  // shows), in batches, gives the same values bit for bit.
  std::vector<double> sum;
  for (int b0 = 0; b0 < Bins; b0 += 4) {
    std::vector<Bitmap> frames = readFrames(volume, b0, std::min(4, Bins - b0));
    accumulateFrames(frames, sum);
    for (size_t k = 0; k < frames.size(); ++k)
      for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
          integral.readBins(y, x, b0 + int(k), 1, pixel.data());
          for (int c = 0; c < 3; ++c) EXPECT_EQ(frames[k].pixel(x, y)[c], pixel[size_t(c)]);
        }
  }
  EXPECT_THROW(writeRunningIntegral(volume, in, in), Error);
}

TEST(TransientView, RunningIntegralStartsFromTheLightBeforeTheWindow) {
  // A continuous render's bins hold the light that arrived before the window
  // too (a step that started earlier fills every bin): so does the running
  // integral of a Dirac render, from <stem>_before.exr when there is one.
  const fs::path in = testDir() / "with_before.npy", out = testDir() / "with_before_integral.npy";
  const std::vector<float> data = writeRandomVolume(in, 11);
  const NpyVolume volume = NpyVolume::open(in);
  EXPECT_FALSE(readBeforeImage(in, W, H).has_value());
  Bitmap before(W, H, 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) before.pixel(x, y)[c] = float(1 + x + 10 * y + 100 * c);
  writeEXR(testDir() / "with_before_before.exr", before);
  const std::optional<Bitmap> read = readBeforeImage(in, W, H);
  ASSERT_TRUE(read.has_value());
  writeRunningIntegral(volume, in, out, &*read);
  const NpyVolume integral = NpyVolume::open(out);
  std::vector<float> pixel(size_t(Bins) * 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      integral.readPixels(y, x, 1, pixel.data());
      for (int c = 0; c < 3; ++c) {
        double sum = before.pixel(x, y)[c];
        for (int b = 0; b < Bins; ++b) {
          sum += data[((size_t(y) * W + x) * Bins + b) * 3 + c];
          EXPECT_NEAR(pixel[size_t(b) * 3 + c], sum, 1e-6 * (1 + sum));
        }
      }
    }
  // The luminance histogram for --running-integral's exposure sees the offset.
  EXPECT_GT(volumeLuminances(volume, 0, Bins, true, &*read).percentile(50.0),
            volumeLuminances(volume, 0, Bins, true).percentile(50.0));
  // A before image of another size is refused, naming it.
  writeEXR(testDir() / "with_before_before.exr", Bitmap(W + 1, H, 3));
  try {
    readBeforeImage(in, W, H);
    ADD_FAILURE() << "no error for a before image of the wrong size";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("with_before_before.exr"), std::string::npos) << e.what();
  }
}

TEST(TransientView, PercentileOfPositiveLuminancesWithinABucket) {
  LuminanceHistogram histogram;
  for (int i = 1; i <= 1000; ++i) histogram.add(float(i));
  for (float ignored : {0.0f, -3.0f, NAN, INFINITY}) histogram.add(ignored);
  EXPECT_EQ(histogram.count(), 1000u);
  const double bucket = std::exp2(1.0 / LuminanceHistogram::BucketsPerOctave);
  for (double p : {10.0, 50.0, 99.5}) {
    const double exact = p * 10.0;  // the p-th percentile of 1..1000
    EXPECT_LE(histogram.percentile(p), exact * bucket) << p;
    EXPECT_GE(histogram.percentile(p), exact / bucket) << p;
  }
  EXPECT_EQ(LuminanceHistogram().percentile(50), 0.0f);
  EXPECT_FLOAT_EQ(exposureForWhite(0.25f), 2.0f);
  EXPECT_EQ(exposureForWhite(0.0f), 0.0f);
}

TEST(TransientView, VolumeLuminancesCountsTheChosenBinsOrTheirRunningSums) {
  const NpyVolume volume = NpyVolume::open(writeHotVoxelVolume("hot_exposure.npy"));
  const float hotLuminance = luminanceOf(Hot);
  EXPECT_EQ(volumeLuminances(volume, 0, Bins, false).count(), 1u);
  EXPECT_EQ(volumeLuminances(volume, 0, HotBin, false).count(), 0u);
  // The running sum keeps the hot value in every later bin.
  EXPECT_EQ(volumeLuminances(volume, 0, Bins, true).count(), uint64_t(Bins - HotBin));
  const float white = volumeLuminances(volume, 0, Bins, false).percentile(99.5);
  EXPECT_NEAR(white / hotLuminance, 1.0, 0.02);
}

TEST(TransientView, FalseColourRampGetsBrighterMonotonically) {
  auto luma = [](Color3f c) { return c.luminance(); };
  EXPECT_LT(luma(falseColourRamp(0.0f)), 0.01f);
  EXPECT_GT(luma(falseColourRamp(1.0f)), 0.9f);
  float previous = -1.0f;
  for (int i = 0; i <= 200; ++i) {
    const float l = luma(falseColourRamp(i / 200.0f));
    EXPECT_GT(l, previous) << i;
    previous = l;
  }
  EXPECT_EQ(falseColourRamp(-1.0f), falseColourRamp(0.0f));
  EXPECT_EQ(falseColourRamp(2.0f), falseColourRamp(1.0f));
}

TEST(TransientView, DisplayImageAppliesOneExposure) {
  Bitmap linear(2, 1, 3);
  std::fill_n(linear.pixel(1, 0), 3, 0.5f);
  const Bitmap grey = displayImage(linear, 1.0f, false);
  EXPECT_FLOAT_EQ(grey.pixel(1, 0)[1], 1.0f);
  EXPECT_EQ(grey.pixel(0, 0)[1], 0.0f);
  const Bitmap colour = displayImage(linear, 1.0f, true);
  // White (exposed luminance 1) becomes the ramp's top colour, black its bottom.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(linearToSRGB(colour.pixel(1, 0)[c]), falseColourRamp(1.0f)[c], 1e-4);
    EXPECT_NEAR(linearToSRGB(colour.pixel(0, 0)[c]), falseColourRamp(0.0f)[c], 1e-4);
  }
}

TEST(TransientView, ContactSheetTilesFramesInOrder) {
  EXPECT_EQ(sheetFrames(10, 4), (std::vector<int>{0, 3, 6, 9}));
  EXPECT_EQ(sheetFrames(3, 16), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(sheetFrames(5, 1), (std::vector<int>{0}));
  ContactSheet sheet(2, 1, 3, 2, 1);  // 2 columns, 2 rows, 1-pixel gutter
  ASSERT_EQ(sheet.image().width, 5);
  ASSERT_EQ(sheet.image().height, 3);
  Bitmap tile(2, 1, 3);
  std::fill(tile.data.begin(), tile.data.end(), 1.0f);
  sheet.place(2, tile);  // second row, first column
  EXPECT_EQ(sheet.image().pixel(0, 2)[0], 1.0f);
  EXPECT_EQ(sheet.image().pixel(1, 2)[0], 1.0f);
  EXPECT_EQ(sheet.image().pixel(3, 2)[0], 0.0f);
  EXPECT_EQ(sheet.image().pixel(0, 0)[0], 0.0f);
  EXPECT_THROW(sheet.place(3, tile), Error);
}

TEST(TransientView, ReadingRefusesWhatIsNotAVolumeInOneSentence) {
  const fs::path dir = testDir();
  auto expectError = [](const fs::path& path, const std::string& fragment) {
    try {
      NpyVolume::open(path);
      ADD_FAILURE() << "opened " << path;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  };
  std::ofstream(dir / "text.npy") << "not a volume at all";
  expectError(dir / "text.npy", "is not a version 1 .npy file");
  std::ofstream(dir / "tiny.npy") << "x";
  expectError(dir / "tiny.npy", "is not a version 1 .npy file");
  // A float64 array: numpy's header with another dtype.
  {
    std::vector<char> header = npyHeader({H, W, Bins, 3});
    std::string text(header.begin(), header.end());
    text.replace(text.find("<f4"), 3, "<f8");
    std::ofstream(dir / "f8.npy", std::ios::binary) << text << std::string(size_t(H) * W * Bins * 3 * 8, '\0');
  }
  expectError(dir / "f8.npy", "is not a float32 C-order (height, width, bins, 3) volume");
  {
    std::vector<char> header = npyHeader({H, W, Bins});
    std::ofstream(dir / "rank3.npy", std::ios::binary).write(header.data(), std::streamsize(header.size()));
  }
  expectError(dir / "rank3.npy", "is not a float32 C-order");
  // A volume cut short.
  const fs::path whole = writeHotVoxelVolume("cut.npy");
  fs::resize_file(whole, fs::file_size(whole) - 4);
  expectError(whole, "is truncated");
}

}  // namespace
}  // namespace femto
