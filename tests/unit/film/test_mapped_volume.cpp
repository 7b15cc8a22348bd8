// MappedVolume (film/mapped_volume.h): frames and pixels read through the
// memory map equal what NpyVolume's pread gives, and a volume larger than
// memory opens at once (a sparse file, so the test needs no disk space).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <random>
#include <vector>

#include <femto/base/error.h>
#include <femto/film/mapped_volume.h>
#include <femto/film/npy_volume.h>

namespace fs = std::filesystem;

namespace femto {
namespace {

fs::path testPath(const std::string& name) {
  fs::path dir = fs::path(::testing::TempDir()) / ("femto_mapped_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

TEST(MappedVolume, FramesAndPixelsMatchPread) {
  constexpr int H = 4, W = 6, Bins = 11;
  const fs::path path = testPath("random.npy");
  std::vector<float> data(size_t(H) * W * Bins * 3);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float& v : data) v = u(rng);
  {
    NpyVolume volume = NpyVolume::create(path, H, W, Bins);
    for (int y = 0; y < H; ++y) volume.writePixels(y, 0, W, &data[size_t(y) * W * Bins * 3]);
  }
  const NpyVolume volume = NpyVolume::open(path);
  const MappedVolume mapped = MappedVolume::open(path);
  ASSERT_EQ(mapped.height(), H);
  ASSERT_EQ(mapped.width(), W);
  ASSERT_EQ(mapped.bins(), Bins);
  std::vector<float> bins(size_t(Bins) * 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      volume.readBins(y, x, 0, Bins, bins.data());
      EXPECT_EQ(std::vector<float>(mapped.pixel(y, x), mapped.pixel(y, x) + Bins * 3), bins) << x << ',' << y;
    }
  for (int b : {0, 5, Bins - 1}) {
    const std::vector<float> frame = mapped.frame(b);
    ASSERT_EQ(frame.size(), size_t(H) * W * 3);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(frame[(size_t(y) * W + x) * 3 + c], data[((size_t(y) * W + x) * Bins + b) * 3 + c]);
  }
  EXPECT_THROW(mapped.frame(Bins), Error);
  EXPECT_THROW(mapped.frame(-1), Error);
}

TEST(MappedVolume, RefusesWhatNpyVolumeRefuses) {
  const fs::path path = testPath("truncated.npy");
  NpyVolume::create(path, 2, 2, 4);
  fs::resize_file(path, fs::file_size(path) - 4);
  try {
    MappedVolume::open(path);
    FAIL() << "a truncated volume was mapped";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
}

// 512 x 512 pixels x 4096 bins x RGB float32 = 12.9 GB, as a sparse file
// (no disk blocks): opening it reads the header and maps it; a frame touches
// one page per pixel. Neither may depend on the volume's size.
TEST(MappedVolume, TwelveGigabyteVolumeOpensAtOnce) {
  constexpr int H = 512, W = 512, Bins = 4096;
  const fs::path path = testPath("large.npy");
  try {
    NpyVolume volume = NpyVolume::create(path, H, W, Bins);
    std::vector<float> pixel(size_t(Bins) * 3, 0.0f);
    pixel[size_t(1000) * 3 + 1] = 2.5f;
    volume.writePixels(H - 1, W - 1, 1, pixel.data());
  } catch (const Error& e) {
    GTEST_SKIP() << "this file system cannot hold a sparse 12.9 GB file: " << e.what();
  }
  // Counted in pages, not seconds (the machine's load stretches time, not
  // work): opening reads the header and maps the file, touching nothing of
  // the data; a frame touches the page (or two, where a pixel's three floats
  // straddle a boundary) holding bin 1000 of each pixel and no more, so the
  // kernel's readahead (dozens of pages around each, a minute for this frame
  // before MADV_RANDOM) is off, and reading the 12.9 GB is not what happens.
  const MappedVolume mapped = MappedVolume::open(path);
  const size_t pixels = size_t(H) * W;
  ASSERT_GT(mapped.mappedPages(), 10 * pixels);
  EXPECT_LE(mapped.residentPages(), 16u) << "opening touched the data";
  const std::vector<float> frame = mapped.frame(1000);
  EXPECT_EQ(frame[(size_t(H - 1) * W + (W - 1)) * 3 + 1], 2.5f);
  EXPECT_EQ(frame[0], 0.0f);
  const size_t touched = mapped.residentPages();
  EXPECT_GE(touched, pixels / 4) << "the frame's pages are not counted";
  EXPECT_LE(touched, 2 * pixels + 16) << "a frame paged in more than its pixels' pages (readahead?)";
  RecordProperty("resident_pages_after_frame", std::to_string(touched));
  fs::remove(path);
}

}  // namespace
}  // namespace femto
