// Mitsuba 0.6's ldrfilm: the tone-mapped 8-bit image against the closed
// forms (exposure, sRGB or power-law gamma; Reinhard et al. 2002's global
// operator), the linear EXR beside it, the format the scene names, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <femto/image/image_io.h>
#include <femto/render/film.h>
#include <femto/render/image_block.h>
#include <femto/xml/loader.h>

#include "loader_test_support.h"
#include "render_test_util.h"

namespace femto {
namespace {

std::shared_ptr<Film> ldrFilm(const std::string& parameters) {
  std::string xml = "<film type=\"ldrfilm\">\n<integer name=\"width\" value=\"2\"/><integer name=\"height\" value=\"1\"/>"
                    "<rfilter type=\"box\"/>" + parameters + "</film>";
  return std::dynamic_pointer_cast<Film>(loadObjectFromString(xml, ".", {}, "ldr.xml"));
}

/// A 2x1 image: pixel 0 = `a`, pixel 1 = `b` (linear RGB), developed to dir/out.*.
Bitmap develop(const Film& film, const Color3f& a, const Color3f& b, const std::filesystem::path& dir) {
  ImageBlock block({0, 0}, {2, 1}, film.filter());
  block.put({0.5f, 0.5f}, a);
  block.put({1.5f, 0.5f}, b);
  film.develop(block, dir / "out.exr");
  return readImage(dir / ("out" + film.defaultExtension()));
}

int byte(float encoded) { return int(std::clamp(encoded, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

TEST(LDRFilm, GammaToneMappingIsExposureThenTheDisplayCurve) {
  auto dir = test::scratchDir("ldrfilm-gamma");
  // sRGB (gamma -1) with one stop of exposure.
  auto srgb = ldrFilm("<float name=\"exposure\" value=\"1\"/>");
  Bitmap a = develop(*srgb, Color3f(0.1f, 0.2f, 0.3f), Color3f(0.8f), dir);
  EXPECT_EQ(int(std::lround(a.pixel(0, 0)[0] * 255.0f)), byte(linearToSRGB(0.2f)));
  EXPECT_EQ(int(std::lround(a.pixel(0, 0)[2] * 255.0f)), byte(linearToSRGB(0.6f)));
  EXPECT_EQ(int(std::lround(a.pixel(1, 0)[1] * 255.0f)), 255) << "0.8 x 2 clamps to white";
  EXPECT_TRUE(std::filesystem::exists(dir / "out.exr")) << "the linear image beside it";
  EXPECT_NEAR(readImage(dir / "out.exr").pixel(0, 0)[1], 0.2f, 1e-6f);
  // A power law, written as JPEG when the scene says so (quantised: one level of slack).
  auto power = ldrFilm("<float name=\"gamma\" value=\"2.2\"/><string name=\"file_format\" value=\"jpeg\"/>");
  EXPECT_EQ(power->defaultExtension(), ".jpg");
  Bitmap b = develop(*power, Color3f(0.25f), Color3f(0.25f), dir);
  EXPECT_NEAR(b.pixel(0, 0)[0] * 255.0f, std::pow(0.25f, 1.0f / 2.2f) * 255.0f, 2.0f);
  std::filesystem::remove_all(dir);
}

TEST(LDRFilm, ReinhardMapsTheBrightestPixelToWhiteAndKeepsColourRatios) {
  auto dir = test::scratchDir("ldrfilm-reinhard");
  auto film = ldrFilm("<string name=\"tonemap_method\" value=\"reinhard\"/><float name=\"gamma\" value=\"1\"/>");
  const Color3f dim(0.2f, 0.1f, 0.05f), bright(4.0f, 4.0f, 4.0f);
  Bitmap out = develop(*film, dim, bright, dir);
  EXPECT_EQ(int(std::lround(out.pixel(1, 0)[0] * 255.0f)), 255);
  // The closed form for the dim pixel (Reinhard et al. 2002, eq. 1-4; gamma 1).
  auto Y = [](const Color3f& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
  double average = std::exp(0.5 * (std::log(1e-4 + Y(dim)) + std::log(1e-4 + Y(bright))));
  double scale = 0.18 / average, white = Y(bright) * scale, l = Y(dim) * scale;
  double ld = l * (1.0 + l / (white * white)) / (1.0 + l);
  EXPECT_NEAR(out.pixel(0, 0)[0] * 255.0f, ld / Y(dim) * dim.r * 255.0, 0.51);
  EXPECT_NEAR(out.pixel(0, 0)[1] * 255.0f, ld / Y(dim) * dim.g * 255.0, 0.51);
  std::filesystem::remove_all(dir);
}

TEST(LDRFilm, BadParametersNameTheirLine) {
  EXPECT_SCENE_ERROR(ldrFilm("\n<string name=\"file_format\" value=\"tiff\"/>"), "ldr.xml:3", "expected \"png\" or \"jpeg\"");
  EXPECT_SCENE_ERROR(ldrFilm("\n<string name=\"tonemap_method\" value=\"aces\"/>"), "ldr.xml:3", "\"gamma\" or \"reinhard\"");
  EXPECT_SCENE_ERROR(ldrFilm("\n<float name=\"burn\" value=\"2\"/>"), "ldr.xml:3", "[0, 1]");
  EXPECT_SCENE_ERROR(ldrFilm("\n<float name=\"gamma\" value=\"0\"/>"), "ldr.xml:3", "-1 (sRGB) or positive");
}

}  // namespace femto
