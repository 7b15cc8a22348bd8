// Value elements: numbers, colours, spectra, vectors and transforms, with
// errors at the element's line.
#include <cmath>

#include "loader_test_support.h"

using namespace femto;
using namespace femto::xml;
using femto::loadertest::buildRecorded;

namespace {
/// The Properties of a single <bsdf> built from `body` (its children).
Properties propsOf(const std::string& body) {
  return buildRecorded("<bsdf type=\"test\">\n" + body + "\n</bsdf>")->props;
}

void expectNear(const Point3f& a, const Point3f& b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}
}  // namespace

TEST(LoaderValues, ScalarsAndStrings) {
  auto p = propsOf("<float name=\"f\" value=\"-.5e1\"/><integer name=\"i\" value=\"-3\"/>"
                   "<boolean name=\"b\" value=\"true\"/><string name=\"s\" value=\"a b\"/>");
  EXPECT_FLOAT_EQ(p.getFloat("f"), -5.0f);
  EXPECT_EQ(p.getInt("i"), -3);
  EXPECT_TRUE(p.getBool("b"));
  EXPECT_EQ(p.getString("s"), "a b");
}

TEST(LoaderValues, BadNumberIsAnErrorAtItsLine) {
  EXPECT_SCENE_ERROR(propsOf("  <float name=\"alpha\" value=\"abc\"/>"), "test.xml:2", "expected a number, got 'abc'");
  EXPECT_SCENE_ERROR(propsOf("\n  <integer name=\"n\" value=\"1.5\"/>"), "test.xml:3", "expected an integer, got '1.5'");
  EXPECT_SCENE_ERROR(propsOf("<boolean name=\"b\" value=\"yes\"/>"), "test.xml:2", "expected \"true\" or \"false\"");
  EXPECT_SCENE_ERROR(propsOf("<float name=\"f\"/>"), "test.xml:2", "<float> needs a value=");
}

TEST(LoaderValues, PointsAndVectors) {
  auto p = propsOf("<point name=\"a\" x=\"1\" z=\"3\"/><vector name=\"b\" value=\"4, 5 6\"/>");
  EXPECT_EQ(p.getPoint("a"), Point3f(1, 0, 3));
  EXPECT_EQ(p.getVector("b"), Vec3f(4, 5, 6));
  EXPECT_EQ(p.type("a"), Properties::Type::Point);
  EXPECT_SCENE_ERROR(propsOf("<point name=\"a\" value=\"1, 2\"/>"), "test.xml:2", "expected three numbers");
}

TEST(LoaderValues, RgbForms) {
  EXPECT_EQ(parseRgb("0.1, 0.2, 0.3"), Color3f(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(parseRgb("0.1 0.2 0.3"), Color3f(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(parseRgb("0.1,0.2,0.3"), Color3f(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(parseRgb("0.5"), Color3f(0.5f));
  // "#rrggbb" is 8-bit sRGB: 0xff -> 1, 0x00 -> 0, 0x80 -> ((128/255 + 0.055)/1.055)^2.4.
  Color3f hex = parseRgb("#ff0080");
  EXPECT_FLOAT_EQ(hex.r, 1.0f);
  EXPECT_FLOAT_EQ(hex.g, 0.0f);
  EXPECT_NEAR(hex.b, std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4), 1e-6);
  EXPECT_THROW(parseRgb("0.1, 0.2"), Error);
  EXPECT_THROW(parseRgb("#12345"), Error);
}

TEST(LoaderValues, SrgbIsDecodedToLinear) {
  auto p = propsOf("<srgb name=\"c\" value=\"0.5, 0.04, 1\"/>");
  Color3f c = p.getColor("c");
  EXPECT_NEAR(c.r, std::pow((0.5 + 0.055) / 1.055, 2.4), 1e-6);
  EXPECT_NEAR(c.g, 0.04 / 12.92, 1e-7);  // the linear segment near black
  EXPECT_FLOAT_EQ(c.b, 1.0f);
}

TEST(LoaderValues, SpectrumConstantAndSampled) {
  EXPECT_EQ(parseSpectrum("0.7"), Color3f(0.7f));
  // A constant sampled spectrum stays that grey.
  Color3f flat = parseSpectrum("400:0.78, 500:0.78, 600:0.78, 700:0.78");
  EXPECT_FLOAT_EQ(flat.r, 0.78f);
  EXPECT_FLOAT_EQ(flat.g, 0.78f);
  EXPECT_FLOAT_EQ(flat.b, 0.78f);
  // A linear ramp v = lambda - 400 averages to its band midpoints: 50, 150, 250.
  Color3f ramp = parseSpectrum("400:0, 700:300");
  EXPECT_NEAR(ramp.b, 50.0f, 1e-4);
  EXPECT_NEAR(ramp.g, 150.0f, 1e-4);
  EXPECT_NEAR(ramp.r, 250.0f, 1e-4);
  // Held constant beyond the samples: a step at 550 nm.
  Color3f step = parseSpectrum("549:0 551:1");
  EXPECT_NEAR(step.b, 0.0f, 1e-6);
  EXPECT_NEAR(step.g, 0.5f, 1e-6);
  EXPECT_NEAR(step.r, 1.0f, 1e-6);
  EXPECT_THROW(parseSpectrum("500:1, 400:2"), Error);  // wavelengths must increase
  EXPECT_SCENE_ERROR(propsOf("<spectrum name=\"s\" value=\"400:x\"/>"), "test.xml:2", "expected a number, got 'x'");
}

TEST(LoaderValues, TransformOpsComposeInDocumentOrder) {
  auto p = propsOf("<transform name=\"tr\"><translate x=\"1\"/><rotate z=\"1\" angle=\"90\"/></transform>\n"
                   "<transform name=\"rt\"><rotate z=\"1\" angle=\"90\"/><translate value=\"1 0 0\"/></transform>");
  // translate then rotate: (0,0,0) -> (1,0,0) -> (0,1,0)
  expectNear(p.getTransform("tr").point(Point3f(0, 0, 0)), Point3f(0, 1, 0));
  // rotate then translate: (0,0,0) -> (0,0,0) -> (1,0,0)
  expectNear(p.getTransform("rt").point(Point3f(0, 0, 0)), Point3f(1, 0, 0));
}

TEST(LoaderValues, ScaleMatrixAndLookAt) {
  auto p = propsOf("<transform name=\"s\"><scale value=\"2\"/><scale y=\"3\"/></transform>"
                   "<transform name=\"m\"><matrix value=\"1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1\"/></transform>"
                   "<transform name=\"l1\"><lookat origin=\"1, 2, 3\" target=\"1, 2, 4\" up=\"0, 1, 0\"/></transform>"
                   "<transform name=\"l2\"><lookAt origin=\"1, 2, 3\" target=\"1, 2, 4\" up=\"0, 1, 0\"/></transform>");
  expectNear(p.getTransform("s").point(Point3f(1, 1, 1)), Point3f(2, 6, 2));
  expectNear(p.getTransform("m").point(Point3f(0, 0, 0)), Point3f(5, 6, 7));
  // Camera space +z looks at the target from the origin.
  expectNear(p.getTransform("l1").point(Point3f(0, 0, 0)), Point3f(1, 2, 3));
  expectNear(p.getTransform("l1").point(Point3f(0, 0, 1)), Point3f(1, 2, 4));
  EXPECT_EQ(p.getTransform("l1").matrix(), p.getTransform("l2").matrix());
}

TEST(LoaderValues, BadTransformOpIsAnErrorAtItsLine) {
  EXPECT_SCENE_ERROR(propsOf("<transform name=\"t\">\n  <shear x=\"1\"/>\n</transform>"), "test.xml:3",
                     "unsupported tag <shear> inside <transform>");
  EXPECT_SCENE_ERROR(propsOf("<transform name=\"t\">\n  <matrix value=\"1 2 3\"/>\n</transform>"), "test.xml:3",
                     "<matrix> needs 16 numbers, got 3");
  EXPECT_SCENE_ERROR(propsOf("<transform name=\"t\">\n  <rotate angle=\"3\"/>\n</transform>"), "test.xml:3",
                     "non-zero axis");
}

TEST(LoaderValues, ParameterGivenTwiceIsAnError) {
  EXPECT_SCENE_ERROR(propsOf("<float name=\"a\" value=\"1\"/>\n<float name=\"a\" value=\"2\"/>"), "test.xml:3",
                     "parameter \"a\" is given twice (first given at test.xml:2)");
}
