// Image files: EXR float round trip, PNG sRGB encoding, atomic writes, errors.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/base/error.h>
#include <femto/image/image_io.h>

#include "render_test_util.h"

namespace femto {
namespace {

Bitmap gradient(int w, int h, int c) {
  Bitmap b(w, h, c);
  for (size_t i = 0; i < b.data.size(); ++i) b.data[i] = std::ldexp(float(i % 7) + 0.125f, int(i % 5) - 3);
  return b;
}

size_t fileCount(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(ImageIO, ExrRoundTripIsExactInFloat32) {
  auto dir = test::scratchDir("exr");
  for (int channels : {1, 3, 4}) {
    Bitmap image = gradient(5, 3, channels);
    image.data[0] = 1e30f;  // beyond half-float range: must survive
    auto path = dir / ("c" + std::to_string(channels) + ".exr");
    writeEXR(path, image);
    Bitmap back = readImage(path);
    ASSERT_EQ(back.width, 5);
    ASSERT_EQ(back.height, 3);
    ASSERT_EQ(back.channels, channels);
    EXPECT_EQ(back.data, image.data);
  }
  EXPECT_EQ(fileCount(dir), 3u);  // no temporary files left behind
  std::filesystem::remove_all(dir);
}

TEST(ImageIO, PngIsSrgbEncodedAndClamped) {
  auto dir = test::scratchDir("png");
  Bitmap image(4, 1, 3);
  const float values[] = {0.0f, 0.002f, 0.5f, 4.0f};
  for (int x = 0; x < 4; ++x)
    for (int c = 0; c < 3; ++c) image.pixel(x, 0)[c] = values[x];
  writePNG(dir / "p.png", image);
  Bitmap back = readImage(dir / "p.png");
  ASSERT_EQ(back.channels, 3);
  for (int x = 0; x < 4; ++x) {
    float expected = std::round(linearToSRGB(std::min(values[x], 1.0f)) * 255.0f) / 255.0f;
    EXPECT_NEAR(back.pixel(x, 0)[1], expected, 1e-6f) << "value " << values[x];
  }
  EXPECT_NEAR(linearToSRGB(0.5f), 0.735357f, 1e-5f);  // IEC 61966-2-1
  EXPECT_FLOAT_EQ(linearToSRGB(0.002f), 12.92f * 0.002f);
  // Exposure scales before encoding: 0.25 * 2^1 == 0.5.
  Bitmap quarter(1, 1, 3);
  quarter.data = {0.25f, 0.25f, 0.25f};
  writePNG(dir / "q.png", quarter, 1.0f);
  EXPECT_NEAR(readImage(dir / "q.png").data[0], std::round(linearToSRGB(0.5f) * 255) / 255, 1e-6f);
  std::filesystem::remove_all(dir);
}

// femto writes grey and RGB PNGs itself (zlib); OpenImageIO (libpng) reads
// them back: an odd size, every byte as written, tagged sRGB.
TEST(ImageIO, PngWriterRoundTripsThroughAnIndependentDecoder) {
  auto dir = test::scratchDir("png-writer");
  for (int channels : {1, 3}) {
    Bitmap image(7, 5, channels);
    for (size_t i = 0; i < image.data.size(); ++i) image.data[i] = float((i * 37) % 256) / 255.0f;
    auto path = dir / ("c" + std::to_string(channels) + ".png");
    writeDisplayImage(path, image);
    ImageFileInfo info;
    Bitmap back = readImage(path, info);
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    ASSERT_EQ(back.channels, channels);
    EXPECT_EQ(info.bitsPerSample, 8);
    EXPECT_TRUE(info.srgbEncoded);
    for (size_t i = 0; i < image.data.size(); ++i)
      ASSERT_EQ(std::lround(back.data[i] * 255.0f), long((i * 37) % 256)) << channels << " channels, sample " << i;
  }
  EXPECT_EQ(fileCount(dir), 2u);
  std::filesystem::remove_all(dir);
}

TEST(ImageIO, ErrorsNameTheFile) {
  auto dir = test::scratchDir("errors");
  try {
    readImage(dir / "missing.exr");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.exr"), std::string::npos) << e.what();
  }
  Bitmap twoChannels(2, 2, 2);
  EXPECT_THROW(writeEXR(dir / "bad.exr", twoChannels), Error);
  EXPECT_EQ(fileCount(dir), 0u);
  std::filesystem::remove_all(dir);
}

TEST(ImageIO, WriteErrorsNameTheGivenPathNotTheTemporary) {
  // /proc refuses new files: OpenEXR and OpenImageIO fail on the hidden
  // temporary the writer made, and the message must say the path given.
  Bitmap image(2, 2, 3);
  for (auto write : {+[](const std::filesystem::path& p, const Bitmap& b) { writeEXR(p, b); },
                     +[](const std::filesystem::path& p, const Bitmap& b) { writeDisplayImage(p, b); },
                     +[](const std::filesystem::path& p, const Bitmap& b) { writeFloatImage(p, b); }})
    for (const char* name : {"/proc/femto-x.exr", "/proc/femto-x.png", "/proc/femto-x.tif"}) {
      try {
        write(name, image);
        ADD_FAILURE() << "writing " << name << " succeeded";
      } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(name), std::string::npos) << message;
        EXPECT_EQ(message.find(".tmp-"), std::string::npos) << message;
      }
    }
}

}  // namespace
}  // namespace femto
