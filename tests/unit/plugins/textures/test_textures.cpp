// Texture plugins (bitmap, checkerboard) and the core's texel lookups: exact
// values at texel centres, bilinear blends between them, wrap modes, sRGB
// decoding, and textures used as a BSDF's reflectance in a render.
#include <gtest/gtest.h>

#include <map>

#include <femto/image/image_io.h>
#include <femto/image/texel_lookup.h>
#include <femto/render/bsdf.h>
#include <femto/render/shape.h>
#include <femto/render/texture.h>

#include "li_estimate.h"
#include "expect_color.h"
#include "plugin_util.h"
#include "render_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

/// A 3 x 2 RGB image whose texels are all different: texel (x, y) = (x, y, 10 + x + 3y) / 10.
Bitmap testImage() {
  Bitmap image(3, 2, 3);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      float* p = image.pixel(x, y);
      p[0] = 0.1f * x;
      p[1] = 0.1f * y;
      p[2] = 0.1f * (10 + x + 3 * y);
    }
  return image;
}

Color3f texelOf(const Bitmap& image, int x, int y) {
  const float* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

SurfaceInteraction atUv(float u, float v) {
  SurfaceInteraction si;
  si.uv = Point2f(u, v);
  return si;
}

std::shared_ptr<Texture> makeBitmap(const std::filesystem::path& file, const std::string& filter = "",
                                    const std::string& wrap = "", int raw = -1) {
  Properties props("bitmap");
  props.setString("filename", file.string());
  if (!filter.empty()) props.setString("filter_type", filter);
  if (!wrap.empty()) props.setString("wrap_mode", wrap);
  if (raw >= 0) props.setBool("raw", raw != 0);
  return makePlugin<Texture>(ObjectKind::Texture, props);
}

class BitmapTextureTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = scratchDir("bitmap-texture");
    image_ = testImage();
    exr_ = dir_ / "texels.exr";
    writeEXR(exr_, image_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_, exr_;
  Bitmap image_;
};

}  // namespace

TEST_F(BitmapTextureTest, BilinearLookupsAreExactAtTexelCentresAndLinearBetween) {
  auto texture = makeBitmap(exr_);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      SCOPED_TRACE(str("texel ", x, ", ", y));
      expectColorNear(texture->eval(atUv((x + 0.5f) / 3.0f, (y + 0.5f) / 2.0f)), texelOf(image_, x, y));
    }
  // Halfway between the centres of texels (0, 0) and (1, 0), and a quarter of
  // the way from (1, 0) toward (1, 1) (row 0 is the top of the image, v = 0).
  expectColorNear(texture->eval(atUv(1.0f / 3.0f, 0.25f)), (texelOf(image_, 0, 0) + texelOf(image_, 1, 0)) * 0.5f);
  expectColorNear(texture->eval(atUv(1.5f / 3.0f, 0.375f)),
                  texelOf(image_, 1, 0) * 0.75f + texelOf(image_, 1, 1) * 0.25f);
  // Centre of the four texels (1..2) x (0..1).
  expectColorNear(texture->eval(atUv(2.0f / 3.0f, 0.5f)),
                  (texelOf(image_, 1, 0) + texelOf(image_, 2, 0) + texelOf(image_, 1, 1) + texelOf(image_, 2, 1)) * 0.25f);
  expectColorNear(texture->mean(), Color3f(0.1f, 0.05f, 1.25f), 1e-6f);  // mean x = 1, mean y = 1/2
}

TEST_F(BitmapTextureTest, NearestLookupsReadTheTexelContainingUv) {
  auto texture = makeBitmap(exr_, "nearest");
  expectColorNear(texture->eval(atUv(0.34f, 0.01f)), texelOf(image_, 1, 0));
  expectColorNear(texture->eval(atUv(0.99f, 0.51f)), texelOf(image_, 2, 1));
}

TEST_F(BitmapTextureTest, WrapModesFoldCoordinatesOutsideTheImage) {
  // Texel columns read at the centres of columns -3 .. 5 (row 0).
  const std::map<std::string, std::vector<int>> expected = {
      {"repeat", {0, 1, 2, 0, 1, 2, 0, 1, 2}},
      {"mirror", {2, 1, 0, 0, 1, 2, 2, 1, 0}},
      {"clamp", {0, 0, 0, 0, 1, 2, 2, 2, 2}},
  };
  for (const auto& [mode, columns] : expected)
    for (const std::string& filter : {"nearest", "bilinear"}) {
      auto texture = makeBitmap(exr_, filter, mode);
      for (int i = -3; i <= 5; ++i) {
        SCOPED_TRACE(str(mode, " ", filter, ": column ", i));
        expectColorNear(texture->eval(atUv((i + 0.5f) / 3.0f, 0.25f)), texelOf(image_, columns[size_t(i + 3)], 0));
      }
    }
  // Between the last and the first column, repeat blends them; clamp does not.
  expectColorNear(makeBitmap(exr_, "bilinear", "repeat")->eval(atUv(1.0f, 0.25f)),
                  (texelOf(image_, 2, 0) + texelOf(image_, 0, 0)) * 0.5f);
  expectColorNear(makeBitmap(exr_, "bilinear", "clamp")->eval(atUv(1.0f, 0.25f)), texelOf(image_, 2, 0));
}

TEST(SRGB, DecodingFollowsIEC61966) {
  EXPECT_EQ(srgbToLinear(0.0f), 0.0f);
  EXPECT_EQ(srgbToLinear(1.0f), 1.0f);
  EXPECT_NEAR(srgbToLinear(0.04045f), 0.0031308f, 1e-6f);  // the two pieces meet here
  EXPECT_NEAR(srgbToLinear(0.5f), 0.2140411f, 1e-6f);
  for (float v = 0.0f; v <= 1.0f; v += 0.01f) EXPECT_NEAR(srgbToLinear(linearToSRGB(v)), v, 2e-6f);
}

TEST_F(BitmapTextureTest, EightBitImagesAreDecodedFromSRGBUnlessRaw) {
  // writePNG stores round(255 * sRGB(v)); the texture must undo the sRGB curve.
  const std::vector<float> linear = {0.0f, 0.01f, 0.05f, 0.2f, 0.5f, 0.8f, 1.0f};
  Bitmap grey(int(linear.size()), 1, 1);
  for (size_t i = 0; i < linear.size(); ++i) grey.data[i] = linear[i];
  auto png = dir_ / "grey.png";
  writePNG(png, grey);
  auto decoded = makeBitmap(png, "nearest");
  auto raw = makeBitmap(png, "nearest", "", 1);
  for (size_t i = 0; i < linear.size(); ++i) {
    SCOPED_TRACE(str("value ", linear[i]));
    float stored = std::round(linearToSRGB(linear[i]) * 255.0f) / 255.0f;
    SurfaceInteraction si = atUv((float(i) + 0.5f) / float(linear.size()), 0.5f);
    expectColorNear(raw->eval(si), Color3f(stored), 1e-6f);
    expectColorNear(decoded->eval(si), Color3f(srgbToLinear(stored)), 1e-6f);
    // And that is the original value up to 8-bit quantisation.
    expectColorNear(decoded->eval(si), Color3f(linear[i]), 5e-3f);
  }
  // Mitsuba 0.6's gamma overrides the file: 1 keeps stored values, 2 squares them.
  for (float gamma : {1.0f, 2.0f}) {
    Properties props("bitmap");
    props.setString("filename", png.string());
    props.setString("filter_type", "nearest");
    props.setFloat("gamma", gamma);
    auto texture = makePlugin<Texture>(ObjectKind::Texture, props);
    for (size_t i = 0; i < linear.size(); ++i) {
      float stored = std::round(linearToSRGB(linear[i]) * 255.0f) / 255.0f;
      expectColorNear(texture->eval(atUv((float(i) + 0.5f) / float(linear.size()), 0.5f)),
                      Color3f(std::pow(stored, gamma)), 1e-6f);
    }
  }
  // Float images are linear already: raw changes nothing.
  SurfaceInteraction centre = atUv(0.5f, 0.25f);
  expectColorNear(makeBitmap(exr_, "", "", 0)->eval(centre), makeBitmap(exr_, "", "", 1)->eval(centre));
}

TEST_F(BitmapTextureTest, LegacyScaleAndOffsetMatchToUv) {
  Properties legacy("bitmap");
  legacy.setString("filename", exr_.string());
  legacy.setFloat("uscale", 2.0f);
  legacy.setFloat("voffset", 0.5f);
  Properties modern("bitmap");
  modern.setString("filename", exr_.string());
  modern.setTransform("to_uv", Transform::translate({0.0f, 0.5f, 0.0f}) * Transform::scale({2.0f, 1.0f, 1.0f}));
  auto a = makePlugin<Texture>(ObjectKind::Texture, legacy), b = makePlugin<Texture>(ObjectKind::Texture, modern);
  for (Point2f uv : {Point2f(0.1f, 0.2f), Point2f(0.4f, 0.9f), Point2f(0.8f, 0.3f)}) {
    expectColorNear(a->eval(atUv(uv.x, uv.y)), b->eval(atUv(uv.x, uv.y)));
    expectColorNear(a->eval(atUv(uv.x, uv.y)), makeBitmap(exr_)->eval(atUv(2.0f * uv.x, uv.y + 0.5f)));
  }
}

TEST_F(BitmapTextureTest, BadParametersAreErrorsNamingTheProblem) {
  Properties wrap("bitmap");
  wrap.setString("filename", exr_.string());
  wrap.setString("wrap_mode", "tile");
  EXPECT_NE(errorMessageOf([&] { makePlugin<Texture>(ObjectKind::Texture, wrap); }).find("unknown wrap mode \"tile\""),
            std::string::npos);
  Properties filter("bitmap");
  filter.setString("filename", exr_.string());
  filter.setString("filter_type", "cubic");
  EXPECT_NE(errorMessageOf([&] { makePlugin<Texture>(ObjectKind::Texture, filter); }).find("unknown filter type"),
            std::string::npos);
  Properties missing("bitmap");
  missing.setString("filename", (dir_ / "nothing.png").string());
  EXPECT_NE(errorMessageOf([&] { makePlugin<Texture>(ObjectKind::Texture, missing); }).find("nothing.png"),
            std::string::npos);
  Properties both("bitmap");
  both.setString("filename", exr_.string());
  both.setFloat("uscale", 2.0f);
  both.setTransform("to_uv", Transform());
  EXPECT_NE(errorMessageOf([&] { makePlugin<Texture>(ObjectKind::Texture, both); }).find("not both"), std::string::npos);
}

namespace {

const Color3f Color0(0.9f, 0.1f, 0.2f), Color1(0.1f, 0.6f, 0.3f);

std::shared_ptr<Texture> makeCheckerboard(const Transform* toUv = nullptr) {
  Properties props("checkerboard");
  props.setColor("color0", Color0);
  props.setColor("color1", Color1);
  if (toUv) props.setTransform("to_uv", *toUv);
  return makePlugin<Texture>(ObjectKind::Texture, props);
}

}  // namespace

TEST(CheckerboardTexture, AlternatesInHalfUnitSquares) {
  auto texture = makeCheckerboard();
  EXPECT_EQ(texture->eval(atUv(0.25f, 0.25f)), Color0);
  EXPECT_EQ(texture->eval(atUv(0.75f, 0.75f)), Color0);
  EXPECT_EQ(texture->eval(atUv(0.75f, 0.25f)), Color1);
  EXPECT_EQ(texture->eval(atUv(0.25f, 0.75f)), Color1);
  // The pattern repeats with period 1, also for negative coordinates.
  EXPECT_EQ(texture->eval(atUv(1.25f, -0.75f)), Color0);
  EXPECT_EQ(texture->eval(atUv(-0.25f, 2.25f)), Color1);
  expectColorNear(texture->mean(), (Color0 + Color1) * 0.5f);
  Transform twice = Transform::scale({2.0f, 2.0f, 1.0f});
  EXPECT_EQ(makeCheckerboard(&twice)->eval(atUv(0.3f, 0.1f)), Color1);  // pattern uv (0.6, 0.2)
}

TEST(CheckerboardTexture, ServesAsDiffuseReflectance) {
  Properties props("diffuse");
  props.setObject("reflectance", makeCheckerboard());
  auto bsdf = makePlugin<BSDF>(ObjectKind::BSDF, props);
  SurfaceInteraction si = atUv(0.75f, 0.25f);
  si.wi = Vec3f(0, 0, 1);
  expectColorNear(bsdf->eval(si, Vec3f(0, 0, 1)), Color1 * InvPi);
}

TEST(CheckerboardTexture, DiffusePlaneUnderAConstantSkyShowsBothColours) {
  // A one-sided diffuse plane under a uniform sky of radiance L sees only the
  // sky, so it reflects rho(uv) L. The rectangle spans [-2, 2]^2 and uv
  // [0, 1]^2, so the point (x, y) has uv ((x / 2 + 1) / 2, (y / 2 + 1) / 2).
  const Color3f L(1.5f, 1.0f, 2.0f);
  auto scene = loadStrict(str(R"(<scene version="3.0.0">
  <integrator type="path"/>
  <shape type="rectangle">
    <transform name="to_world"><scale value="2"/></transform>
    <bsdf type="diffuse">
      <texture type="checkerboard" name="reflectance">
        <rgb name="color0" value=")", rgb(Color0), R"("/>
        <rgb name="color1" value=")", rgb(Color1), R"("/>
      </texture>
    </bsdf>
  </shape>
  <emitter type="constant"><rgb name="radiance" value=")", rgb(L), R"("/></emitter>
</scene>)"));
  const Point3f eye(0.3f, -0.4f, 6.0f);
  const std::pair<Point3f, Color3f> cases[] = {
      {Point3f(-1, -1, 0), Color0}, {Point3f(1, -1, 0), Color1}, {Point3f(1, 1, 0), Color0}, {Point3f(-1, 1, 0), Color1}};
  for (const auto& [target, rho] : cases) {
    SCOPED_TRACE(str("point ", target));
    expectWithinErrorBars(estimateLi(*scene, 4000, [&](PCG32&) { return Ray(eye, normalize(target - eye)); }), rho * L);
  }
}

TEST_F(BitmapTextureTest, MitsubaLegacySceneLoadsStrictlyWithUpgradedNames) {
  // Mitsuba 0.6 spellings: the loader turns wrapModeU into wrap_mode_u and
  // filterType into filter_type, and keeps uscale as it is.
  LoadOptions options;
  options.strict = true;
  auto scene = loadSceneFromString(R"(<scene version="0.6.0">
  <shape type="rectangle">
    <bsdf type="diffuse">
      <texture type="bitmap" name="reflectance">
        <string name="filename" value="texels.exr"/>
        <float name="uscale" value="2"/>
        <string name="wrapModeU" value="mirror"/>
        <string name="wrapModeV" value="clamp"/>
        <string name="filterType" value="nearest"/>
      </texture>
    </bsdf>
  </shape>
</scene>)", dir_, options, "<legacy texture test>");
  const BSDF* bsdf = scene->shapes().at(0)->bsdf();
  ASSERT_NE(bsdf, nullptr);
  auto reflectanceAt = [&](float u, float v) {
    SurfaceInteraction si = atUv(u, v);
    si.wi = Vec3f(0, 0, 1);
    return bsdf->eval(si, Vec3f(0, 0, 1)) * Pi;
  };
  // u = 0.55 -> 1.1 (column 3): mirrored to column 2 (repeat would give 0).
  expectColorNear(reflectanceAt(0.55f, 0.25f), texelOf(image_, 2, 0), 1e-5f);
  // v = 1.3 is clamped to the bottom row.
  expectColorNear(reflectanceAt(0.1f, 1.3f), texelOf(image_, 0, 1), 1e-5f);
}
