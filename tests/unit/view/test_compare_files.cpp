// femto compare's library (analysis/compare_files.h): metrics of images and
// streamed volumes on tiny files with hand-computed answers, regions, time
// windows, and the one-sentence errors for inputs that do not match.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <femto/analysis/compare_files.h>
#include <femto/base/error.h>

#include "compare_test_files.h"
#include "plugin_util.h"
#include "render_test_util.h"

namespace femto {
namespace {

namespace fs = std::filesystem;

using test::errorMessageOf;

// Reference 0.5 everywhere; the test differs by +1 in channel 0 of pixel (1, 1).
float flat(int, int, int) { return 0.5f; }
float bumped(int x, int y, int c) { return x == 1 && y == 1 && c == 0 ? 1.5f : 0.5f; }

TEST(CompareFiles, ImagesMetricsMatchTheHandComputedValues) {
  fs::path dir = test::scratchDir("compare-images");
  test::writeTestImage(dir / "ref.exr", 4, 3, 3, flat);
  test::writeTestImage(dir / "test.exr", 4, 3, 3, bumped);
  Comparison c = compareFiles(dir / "ref.exr", dir / "test.exr", {});
  EXPECT_FALSE(c.transient);
  EXPECT_EQ(c.pixels, 12u);
  const double n = 4 * 3 * 3;
  EXPECT_NEAR(c.metrics.mse, 1.0 / n, 1e-12);
  EXPECT_NEAR(c.metrics.relMse, 1.0 / (0.25 + 0.01) / n, 1e-12);
  EXPECT_NEAR(c.metrics.mae, 1.0 / n, 1e-12);
  EXPECT_EQ(c.metrics.maxError, 1.0);
  EXPECT_NEAR(psnr(c.metrics.mse, c.metrics.referencePeak), 10.0 * std::log10(0.25 * n), 1e-9);
}

TEST(CompareFiles, CropAndMaskSelectThePixelsCounted) {
  fs::path dir = test::scratchDir("compare-region");
  test::writeTestImage(dir / "ref.exr", 4, 3, 3, flat);
  test::writeTestImage(dir / "test.exr", 4, 3, 3, bumped);
  CompareSettings crop;
  crop.crop = PixelRect{1, 0, 2, 2};  // 4 pixels, including the bumped one
  Comparison c = compareFiles(dir / "ref.exr", dir / "test.exr", crop);
  EXPECT_EQ(c.pixels, 4u);
  EXPECT_NEAR(c.metrics.mse, 1.0 / 12, 1e-12);

  // Mask: only the left column (which does not contain the bump) is nonzero.
  test::writeTestImage(dir / "mask.exr", 4, 3, 1, [](int x, int, int) { return x == 0 ? 1.0f : 0.0f; });
  CompareSettings mask;
  mask.mask = dir / "mask.exr";
  c = compareFiles(dir / "ref.exr", dir / "test.exr", mask);
  EXPECT_EQ(c.pixels, 3u);
  EXPECT_EQ(c.metrics.mse, 0.0);

  crop.crop = PixelRect{3, 0, 2, 1};
  EXPECT_EQ(errorMessageOf([&] { compareFiles(dir / "ref.exr", dir / "test.exr", crop); }),
            "the crop 3,0,2,1 reaches outside the 4x3 image");
}

// Volume: reference 1 in every value; the test has +2 in bin 1 of pixel
// (0, 0), channel 2, and +1 in every value of bin 3.
float volumeRef(int, int, int, int) { return 1.0f; }
float volumeTest(int x, int y, int b, int c) {
  return 1.0f + (x == 0 && y == 0 && b == 1 && c == 2 ? 2.0f : 0.0f) + (b == 3 ? 1.0f : 0.0f);
}

TEST(CompareFiles, VolumesGiveOverallPerBinAndTimeIntegralErrors) {
  fs::path dir = test::scratchDir("compare-volumes");
  const int W = 3, H = 2, Bins = 4;
  test::writeTestVolume(dir / "ref.npy", W, H, Bins, volumeRef, test::testGrid(Bins));
  test::writeTestVolume(dir / "test.npy", W, H, Bins, volumeTest, test::testGrid(Bins));
  Comparison c = compareFiles(dir / "ref.npy", dir / "test.npy", {});
  ASSERT_TRUE(c.transient);
  ASSERT_TRUE(c.grid.has_value());
  EXPECT_EQ(c.grid->start, 1.0);
  EXPECT_EQ(c.pixels, size_t(W * H));
  const double valuesPerBin = W * H * 3;
  // Squared errors: 4 once (bin 1) and 1 for each value of bin 3.
  EXPECT_NEAR(c.metrics.mse, (4.0 + valuesPerBin) / (valuesPerBin * Bins), 1e-12);
  EXPECT_NEAR(c.metrics.relMse, (4.0 + valuesPerBin) / 1.01 / (valuesPerBin * Bins), 1e-12);
  EXPECT_EQ(c.metrics.maxError, 2.0);
  ASSERT_EQ(c.perBin.size(), size_t(Bins));
  EXPECT_EQ(c.perBin[0].mse, 0.0);
  EXPECT_NEAR(c.perBin[1].mse, 4.0 / valuesPerBin, 1e-12);
  EXPECT_EQ(c.perBin[2].mse, 0.0);
  EXPECT_NEAR(c.perBin[3].mse, 1.0, 1e-12);
  // Time integral: reference 4 per value; test 5, and 7 for pixel (0, 0) channel 2.
  EXPECT_NEAR(c.integral.mse, (1.0 * (valuesPerBin - 1) + 9.0) / valuesPerBin, 1e-12);
  EXPECT_NEAR(c.integral.relMse, (1.0 * (valuesPerBin - 1) + 9.0) / (16.0 + 0.01) / valuesPerBin, 1e-12);
  EXPECT_EQ(c.integral.maxError, 3.0);
}

TEST(CompareFiles, BinWindowRestrictsEveryVolumeMetric) {
  fs::path dir = test::scratchDir("compare-bins");
  test::writeTestVolume(dir / "ref.npy", 3, 2, 4, volumeRef, test::testGrid(4));
  test::writeTestVolume(dir / "test.npy", 3, 2, 4, volumeTest, test::testGrid(4));
  CompareSettings s;
  s.bins = parseBinRange("2:", "--bins");
  s.binsGiven = true;
  Comparison c = compareFiles(dir / "ref.npy", dir / "test.npy", s);
  EXPECT_EQ(c.binBegin, 2);
  EXPECT_EQ(c.binEnd, 4);
  ASSERT_EQ(c.perBin.size(), 2u);
  EXPECT_NEAR(c.metrics.mse, 0.5, 1e-12);  // bin 2 exact, bin 3 off by 1
  EXPECT_NEAR(c.integral.mse, 1.0, 1e-12);  // sums 2 vs 3 everywhere
  s.bins = parseBinRange("1:9", "--bins");
  EXPECT_EQ(errorMessageOf([&] { compareFiles(dir / "ref.npy", dir / "test.npy", s); }),
            "--bins 1:9 is not a non-empty range inside the 4 time bins of the volumes (0:4)");
  EXPECT_EQ(errorMessageOf([] { parseBinRange("3", "--bins"); }),
            "--bins expects FIRST:END with bin numbers >= 0 (end exclusive, either may be left out), got \"3\"");
}

TEST(CompareFiles, VolumesWithoutSidecarsAreComparedByShape) {
  fs::path dir = test::scratchDir("compare-nosidecar");
  test::writeTestVolume(dir / "ref.npy", 2, 2, 3, volumeRef);
  test::writeTestVolume(dir / "test.npy", 2, 2, 3, volumeRef, test::testGrid(3));
  Comparison c = compareFiles(dir / "ref.npy", dir / "test.npy", {});
  EXPECT_FALSE(c.grid.has_value());
  EXPECT_EQ(c.metrics.mse, 0.0);
}

TEST(CompareFiles, MismatchedInputsAreOneSentenceNamingBothFiles) {
  fs::path dir = test::scratchDir("compare-mismatch");
  auto vol = [&](const char* name, int w, int bins, std::optional<TimeGrid> grid) {
    test::writeTestVolume(dir / name, w, 2, bins, volumeRef, grid);
    return dir / name;
  };
  fs::path ref = vol("ref.npy", 3, 4, test::testGrid(4));
  auto message = [&](const fs::path& test, const CompareSettings& s = {}) {
    return errorMessageOf([&] { compareFiles(ref, test, s); });
  };
  std::string r = "REF \"" + ref.string() + "\"";
  fs::path bins = vol("bins.npy", 3, 8, test::testGrid(8));
  EXPECT_EQ(message(bins), r + " has 4 time bins, TEST \"" + bins.string() + "\" has 8");
  fs::path narrow = vol("narrow.npy", 2, 4, test::testGrid(4));
  EXPECT_EQ(message(narrow), r + " is 3x2, TEST \"" + narrow.string() + "\" is 2x2");
  fs::path shifted = vol("shifted.npy", 3, 4, test::testGrid(4, 2.0));
  EXPECT_EQ(message(shifted), r + " covers 4 bins of OPL 0.5 from 1 to 3, TEST \"" + shifted.string() +
                                  "\" covers 4 bins of OPL 0.5 from 2 to 4");
  test::writeTestImage(dir / "image.exr", 3, 2, 3, flat);
  EXPECT_EQ(message(dir / "image.exr"),
            r + " is a transient volume (.npy), TEST \"" + (dir / "image.exr").string() + "\" is an image");
  EXPECT_EQ(message(dir / "missing.npy"), "\"" + (dir / "missing.npy").string() + "\" does not exist");

  test::writeTestImage(dir / "gray.exr", 3, 2, 1, flat);
  test::writeTestImage(dir / "small.exr", 2, 2, 3, flat);
  std::string img = "REF \"" + (dir / "image.exr").string() + "\"";
  EXPECT_EQ(errorMessageOf([&] { compareFiles(dir / "image.exr", dir / "gray.exr", {}); }),
            img + " has 3 channels, TEST \"" + (dir / "gray.exr").string() + "\" has 1");
  EXPECT_EQ(errorMessageOf([&] { compareFiles(dir / "image.exr", dir / "small.exr", {}); }),
            img + " is 3x2, TEST \"" + (dir / "small.exr").string() + "\" is 2x2");
  CompareSettings bad;
  bad.binsGiven = true;
  EXPECT_EQ(errorMessageOf([&] { compareFiles(dir / "image.exr", dir / "image.exr", bad); }),
            "--bins applies to transient volumes (.npy); " + img + " and TEST \"" + (dir / "image.exr").string() +
                "\" are images");
  CompareSettings mask;
  mask.mask = dir / "small.exr";
  EXPECT_EQ(errorMessageOf([&] { compareFiles(dir / "image.exr", dir / "image.exr", mask); }),
            "the mask \"" + (dir / "small.exr").string() + "\" is 2x2, the images are 3x2");
}

TEST(CompareFiles, TruncatedVolumeIsRefusedWhenOpened) {
  fs::path dir = test::scratchDir("compare-truncated");
  test::writeTestVolume(dir / "ref.npy", 2, 2, 3, volumeRef);
  test::writeTestVolume(dir / "cut.npy", 2, 2, 3, volumeRef);
  const uintmax_t size = fs::file_size(dir / "cut.npy");
  fs::resize_file(dir / "cut.npy", size - 4);
  EXPECT_EQ(errorMessageOf([&] { compareFiles(dir / "ref.npy", dir / "cut.npy", {}); }),
            "\"" + (dir / "cut.npy").string() + "\" is truncated: a (2, 2, 3, 3) volume needs " + std::to_string(size) +
                " bytes, the file has " + std::to_string(size - 4));
}

TEST(CompareFiles, CropTextIsParsedAndBadFormsRefused) {
  EXPECT_EQ(errorMessageOf([] { parsePixelRect("1,2,3", "--crop"); }),
            "--crop expects x,y,width,height (whole numbers), got \"1,2,3\"");
  EXPECT_EQ(errorMessageOf([] { parsePixelRect("1,2,0,4", "--crop"); }),
            "--crop expects x,y >= 0 and width,height >= 1, got \"1,2,0,4\"");
  PixelRect r = parsePixelRect("1,2,3,4", "--crop");
  EXPECT_EQ(r.x + r.y + r.width + r.height, 10);
}

}  // namespace
}  // namespace femto
