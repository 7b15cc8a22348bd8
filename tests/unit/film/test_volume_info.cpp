// The sidecar of a transient volume (<stem>.json, film/volume_info.h): the
// film writes its time window and crop there, readers get them back, and a
// broken sidecar is an error naming the file and line. Also the small JSON
// reader it uses (core/flat_json.h).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <femto/base/error.h>
#include <femto/core/flat_json.h>
#include <femto/film/volume_info.h>

#include "plugin_util.h"
#include "transient_film_test_util.h"

namespace femto {
namespace {

namespace fs = std::filesystem;

TEST(VolumeInfo, TransientRenderWritesTheWindowAndCropBesideTheVolume) {
  fs::path dir = test::scratchDir("volume-info-render");
  Properties film("transient");
  film.setInt("width", 40);
  film.setInt("height", 30);
  film.setInt("crop_offset_x", 4);
  film.setInt("crop_offset_y", 3);
  film.setInt("crop_width", 20);
  film.setInt("crop_height", 5);
  film.setInt("temporal_bins", 16);
  film.setFloat("start_opl", 2.5);
  film.setFloat("bin_width_opl", 0.25);
  film.setString("time_filter", "tent");
  film.setBool("write_frames", false);
  auto scene = test::makeRampScene(film, Properties("test_transient_ramp"), 1);
  RenderOptions options;
  options.output = dir / "out.exr";
  options.progress = false;
  scene->integrator().render(*scene, options);

  EXPECT_EQ(volumeInfoPath(dir / "out.npy"), dir / "out.json");
  std::optional<VolumeInfo> info = readVolumeInfo(dir / "out.npy");
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->width, 20);
  EXPECT_EQ(info->height, 5);
  EXPECT_EQ(info->grid.bins, 16);
  EXPECT_EQ(info->grid.start, 2.5);
  EXPECT_EQ(info->grid.binWidth, 0.25);
  EXPECT_EQ(info->filmSize, Point2i(40, 30));
  EXPECT_EQ(info->cropOffset, Point2i(4, 3));
  EXPECT_EQ(info->timeFilter, "tent");
  // How it was rendered: one pass of the sampler's one sample, no time limit.
  ASSERT_TRUE(info->render.has_value());
  EXPECT_EQ(info->render->passes, 1);
  EXPECT_EQ(info->render->samplesPerPass, 1);
  EXPECT_EQ(info->render->timeLimit, 0.0);
  fs::remove_all(dir);
}

TEST(VolumeInfo, RenderRecordReadsBackAndOlderSidecarsHaveNone) {
  fs::path dir = test::scratchDir("volume-info-record");
  VolumeInfo info;
  info.width = info.height = 2;
  info.grid = TimeGrid{0.0, 1.0, 4};
  writeVolumeInfo(dir / "old.json", info);
  EXPECT_FALSE(readVolumeInfo(dir / "old.npy")->render.has_value());
  info.render = RenderRecord{12, 4, 7, 30.0, "cpu", true};
  writeVolumeInfo(dir / "new.json", info);
  std::ifstream in(dir / "new.json");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("\"spp\": 48"), std::string::npos) << text;  // passes x spp_per_pass, for readers
  std::optional<RenderRecord> back = readVolumeInfo(dir / "new.npy")->render;
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->passes, 12);
  EXPECT_EQ(back->samplesPerPass, 4);
  EXPECT_EQ(back->seed, 7u);
  EXPECT_EQ(back->timeLimit, 30.0);
  EXPECT_EQ(back->timeClock, "cpu");
  EXPECT_TRUE(back->timeLimitReached);
  fs::remove_all(dir);
}

TEST(VolumeInfo, WrittenInfoReadsBackExactly) {
  fs::path dir = test::scratchDir("volume-info-roundtrip");
  VolumeInfo info;
  info.width = 7, info.height = 5;
  info.grid = TimeGrid{0.1, 1.0 / 3.0, 99};  // binary fractions that need all 17 digits
  info.filmSize = {9, 8};
  info.cropOffset = {1, 2};
  writeVolumeInfo(dir / "v.json", info);
  std::optional<VolumeInfo> back = readVolumeInfo(dir / "v.npy");
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->grid.start, 0.1);
  EXPECT_EQ(back->grid.binWidth, 1.0 / 3.0);
  EXPECT_EQ(back->grid.bins, 99);
  EXPECT_EQ(back->cropOffset, Point2i(1, 2));
  EXPECT_TRUE(sameTimeWindow(back->grid, info.grid));
  EXPECT_FALSE(readVolumeInfo(dir / "none.npy").has_value());
  fs::remove_all(dir);
}

TEST(VolumeInfo, SameTimeWindowToleratesFloatRoundingOnly) {
  TimeGrid a{3.0, 0.02, 512};
  TimeGrid b{3.0 + 1e-9, 0.02 * (1 + 1e-9), 512};
  EXPECT_TRUE(sameTimeWindow(a, b));
  EXPECT_FALSE(sameTimeWindow(a, TimeGrid{3.0, 0.02, 256}));
  EXPECT_FALSE(sameTimeWindow(a, TimeGrid{3.01, 0.02, 512}));
  EXPECT_FALSE(sameTimeWindow(a, TimeGrid{3.0, 0.0201, 512}));
  EXPECT_EQ(describeTimeWindow(a), "512 bins of OPL 0.02 from 3 to 13.24");
}

TEST(VolumeInfo, BrokenSidecarIsAnErrorNamingFileAndLine) {
  fs::path dir = test::scratchDir("volume-info-broken");
  std::ofstream(dir / "v.json") << "{\n  \"format\": \"femto transient volume\",\n  \"width\": oops\n}\n";
  EXPECT_EQ(test::errorMessageOf([&] { readVolumeInfo(dir / "v.npy"); }),
            (dir / "v.json").string() + ":3: invalid JSON: expected a value");
  std::ofstream(dir / "w.json") << "{\"format\": \"femto transient volume\", \"width\": 2}";
  EXPECT_EQ(test::errorMessageOf([&] { readVolumeInfo(dir / "w.npy"); }),
            "volume sidecar \"" + (dir / "w.json").string() + "\": missing \"height\"");
  std::ofstream(dir / "x.json") << "{\"something\": 1}";
  EXPECT_NE(test::errorMessageOf([&] { readVolumeInfo(dir / "x.npy"); }).find("is not a femto volume sidecar"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(FlatJson, ReadsNumbersStringsBooleansNullAndNumberArrays) {
  FlatJson j = parseFlatJson(R"({"a": -1.5e2, "s": "x\"y\\z", "t": true, "f": false, "n": null, "v": [1, 2.5], "e": []})",
                             "t.json");
  EXPECT_EQ(std::get<double>(j["a"]), -150.0);
  EXPECT_EQ(std::get<std::string>(j["s"]), "x\"y\\z");
  EXPECT_EQ(std::get<bool>(j["t"]), true);
  EXPECT_EQ(std::get<bool>(j["f"]), false);
  EXPECT_TRUE(std::holds_alternative<std::nullptr_t>(j["n"]));
  EXPECT_EQ(std::get<std::vector<double>>(j["v"]), (std::vector<double>{1.0, 2.5}));
  EXPECT_TRUE(std::get<std::vector<double>>(j["e"]).empty());
}

TEST(FlatJson, RefusesWhatItDoesNotRead) {
  EXPECT_EQ(test::errorMessageOf([] { parseFlatJson("{\"a\": {\"b\": 1}}", "t.json"); }),
            "t.json:1: invalid JSON: nested objects are not supported here");
  EXPECT_EQ(test::errorMessageOf([] { parseFlatJson("{\"a\": 1} x", "t.json"); }),
            "t.json:1: invalid JSON: unexpected text after the object");
  EXPECT_EQ(test::errorMessageOf([] { parseFlatJson("{\"a\": 1", "t.json"); }),
            "t.json:1: invalid JSON: expected ',' or '}' after a value");
  EXPECT_EQ(jsonNumber(0.1), "0.1");
  EXPECT_EQ(jsonNumber(1.0 / 0.0), "null");
  EXPECT_EQ(jsonQuote("a\"b\n"), "\"a\\\"b\\n\"");
}

}  // namespace
}  // namespace femto
