#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include <femto/core/properties.h>
#include <femto/scattering/ior.h>

using namespace femto;

namespace {
SourceLocation at(int line) { return {"scene.xml", line}; }

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Properties, TypedValuesRoundTrip) {
  Properties p("diffuse");
  p.setBool("b", true);
  p.setInt("i", -7);
  p.setFloat("f", 0.25);
  p.setString("s", "hello");
  p.setPoint("p", Point3f(1, 2, 3));
  p.setVector("v", Vec3f(4, 5, 6));
  p.setColor("c", Color3f(0.1f, 0.2f, 0.3f));
  p.setTransform("t", Transform::translate(Vec3f(1, 0, 0)));
  EXPECT_TRUE(p.getBool("b"));
  EXPECT_EQ(p.getInt("i"), -7);
  EXPECT_FLOAT_EQ(p.getFloat("f"), 0.25f);
  EXPECT_EQ(p.getString("s"), "hello");
  EXPECT_EQ(p.getPoint("p"), Point3f(1, 2, 3));
  EXPECT_EQ(p.getVector("v"), Vec3f(4, 5, 6));
  EXPECT_EQ(p.getColor("c"), Color3f(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(p.getTransform("t").point(Point3f(0, 0, 0)), Point3f(1, 0, 0));
  EXPECT_EQ(p.names(), (std::vector<std::string>{"b", "i", "f", "s", "p", "v", "c", "t"}));
  EXPECT_EQ(p.type("c"), Properties::Type::Color);
}

TEST(Properties, DefaultsWhenAbsentAndWideningConversions) {
  Properties p("x");
  p.setInt("n", 3);
  p.setFloat("grey", 0.5);
  EXPECT_FLOAT_EQ(p.getFloat("missing", 2.0f), 2.0f);
  EXPECT_FLOAT_EQ(p.getFloat("n"), 3.0f);               // integer where a float is expected
  EXPECT_EQ(p.getColor("grey"), Color3f(0.5f));         // float where a colour is expected
}

TEST(Properties, TypeErrorsAreInXmlWordsWithTheParameterLine) {
  Properties p("diffuse");
  p.setLocation(at(3));
  p.setColor("reflectance", Color3f(1.0f), at(4));
  EXPECT_EQ(errorOf([&] { p.getFloat("reflectance"); }),
            "scene.xml:4: parameter \"reflectance\" of \"diffuse\": expected <float>, got <rgb>");
  p.setString("name", "x", at(5));
  EXPECT_EQ(errorOf([&] { p.getInt("name"); }),
            "scene.xml:5: parameter \"name\" of \"diffuse\": expected <integer>, got <string>");
}

TEST(Properties, MissingRequiredParameterNamesTheObjectLine) {
  Properties p("sphere");
  p.setLocation(at(9));
  EXPECT_EQ(errorOf([&] { p.getFloat("radius"); }),
            "scene.xml:9: \"sphere\" is missing the required parameter \"radius\" (<float>)");
}

TEST(Properties, GivenTwiceIsAnErrorNamingBothLines) {
  Properties p("x");
  p.setFloat("a", 1, at(2));
  EXPECT_EQ(errorOf([&] { p.setFloat("a", 2, at(3)); }),
            "scene.xml:3: parameter \"a\" is given twice (first given at scene.xml:2)");
}

TEST(Properties, UnqueriedTracksWhatNobodyRead) {
  Properties p("x");
  p.setFloat("a", 1);
  p.setFloat("b", 2);
  p.setFloat("c", 3);
  EXPECT_EQ(p.unqueried(), (std::vector<std::string>{"a", "b", "c"}));
  p.getFloat("b");
  p.getFloat("c", 0.0f);
  EXPECT_EQ(p.unqueried(), (std::vector<std::string>{"a"}));
  EXPECT_TRUE(p.wasQueried("b"));
  EXPECT_FALSE(p.wasQueried("a"));
  p.markQueried("a");
  EXPECT_TRUE(p.unqueried().empty());
}

TEST(Properties, DidYouMeanUsesNamesThePluginAskedFor) {
  Properties p("diffuse");
  p.setColor("reflectanse", Color3f(1.0f));
  EXPECT_EQ(p.getColor("reflectance", Color3f(0.5f)), Color3f(0.5f));  // asked, absent
  EXPECT_FALSE(p.has("two_sided"));                                    // has() also counts as asking
  EXPECT_EQ(p.askedNames(), (std::vector<std::string>{"reflectance", "two_sided"}));
  EXPECT_EQ(p.unqueried(), (std::vector<std::string>{"reflectanse"}));
  EXPECT_EQ(p.suggestionFor("reflectanse"), " (did you mean \"reflectance\"?)");
  EXPECT_EQ(p.suggestionFor("completely_unrelated"), "");
}

TEST(NamedIor, TableValues) {
  EXPECT_FLOAT_EQ(*lookupIOR("vacuum"), 1.0f);
  EXPECT_FLOAT_EQ(*lookupIOR("water"), 1.333f);
  EXPECT_FLOAT_EQ(*lookupIOR("bk7"), 1.5046f);
  EXPECT_FLOAT_EQ(*lookupIOR("diamond"), 2.419f);
  EXPECT_FLOAT_EQ(*lookupIOR("acrylic glass"), 1.49f);
  EXPECT_FALSE(lookupIOR("unobtainium").has_value());
}

TEST(NamedIor, FromPropertiesAcceptsNumbersAndNames) {
  Properties p("dielectric");
  p.setString("int_ior", "water", at(4));
  p.setFloat("ext_ior", 1.2, at(5));
  EXPECT_FLOAT_EQ(iorFromProperties(p, "int_ior", 1.5f), 1.333f);
  EXPECT_FLOAT_EQ(iorFromProperties(p, "ext_ior", 1.0f), 1.2f);
  EXPECT_FLOAT_EQ(iorFromProperties(p, "absent", 1.5f), 1.5f);
  EXPECT_TRUE(p.unqueried().empty());
}

TEST(NamedIor, UnknownNameIsAnErrorAtItsLine) {
  Properties p("dielectric");
  p.setString("int_ior", "watr", at(7));
  p.setFloat("ext_ior", -1, at(8));
  std::string message = errorOf([&] { iorFromProperties(p, "int_ior", 1.5f); });
  EXPECT_EQ(message.rfind("scene.xml:7: parameter \"int_ior\" of \"dielectric\": unknown material \"watr\"", 0), 0u)
      << message;
  EXPECT_NE(message.find("did you mean \"water\""), std::string::npos) << message;
  EXPECT_NE(errorOf([&] { iorFromProperties(p, "ext_ior", 1.0f); }).find("scene.xml:8: "), std::string::npos);
}

// Checked getters: ranges, enumerations and their messages.

TEST(PropertiesChecked, IntegerRangeIsInclusiveAndTheDefaultIsUnchecked) {
  Properties p("film");
  p.setLocation(at(2));
  p.setInt("low", 1, at(3));
  p.setInt("high", 1048576, at(4));
  p.setInt("zero", 0, at(5));
  EXPECT_EQ(p.getInt("low", 7, 1, 1 << 20), 1);
  EXPECT_EQ(p.getInt("high", 7, 1, 1 << 20), 1 << 20);
  EXPECT_EQ(p.getInt("absent", 7, 1, 5), 7);  // a default outside the range is the plugin's business
  EXPECT_EQ(errorOf([&] { p.getInt("zero", 7, 1, 1 << 20); }),
            "scene.xml:5: parameter \"zero\" of \"film\": must be in [1, 1048576], got 0");
  EXPECT_EQ(errorOf([&] { p.getInt("high", 7, 1, (1 << 20) - 1); }),
            "scene.xml:4: parameter \"high\" of \"film\": must be in [1, 1048575], got 1048576");
  EXPECT_TRUE(p.unqueried().empty());
}

TEST(PropertiesChecked, IntegerWithoutUpperBoundAndNote) {
  Properties p("path");
  p.setInt("max_depth", -2, at(6));
  EXPECT_EQ(errorOf([&] { p.getInt("max_depth", -1, -1, Properties::Unbounded, "-1: no limit"); }),
            "scene.xml:6: parameter \"max_depth\" of \"path\": must be at least -1 (-1: no limit), got -2");
}

TEST(PropertiesChecked, RequiredIntegerIsMissingAtTheObjectLine) {
  Properties p("film");
  p.setLocation(at(8));
  EXPECT_EQ(errorOf([&] { p.getIntIn("bins", 1, 10); }),
            "scene.xml:8: \"film\" is missing the required parameter \"bins\" (<integer>)");
  p.setInt("bins", 11, at(9));
  EXPECT_EQ(errorOf([&] { p.getIntIn("bins", 1, 10); }),
            "scene.xml:9: parameter \"bins\" of \"film\": must be in [1, 10], got 11");
}

TEST(PropertiesChecked, FloatRangeEndsAreOpenOrClosed) {
  Properties p("x");
  p.setFloat("zero", 0.0, at(2));
  p.setFloat("one", 1.0, at(3));
  EXPECT_FLOAT_EQ(p.getFloat("zero", 0.5f, Range::closed(0, 1)), 0.0f);
  EXPECT_FLOAT_EQ(p.getFloat("one", 0.5f, Range::closed(0, 1)), 1.0f);
  EXPECT_FLOAT_EQ(p.getFloat("one", 0.5f, Range::leftOpen(0, 1)), 1.0f);
  EXPECT_FLOAT_EQ(p.getFloat("zero", 0.5f, Range::rightOpen(0, 1)), 0.0f);
  EXPECT_EQ(errorOf([&] { p.getFloat("zero", 0.5f, Range::leftOpen(0, 1)); }),
            "scene.xml:2: parameter \"zero\" of \"x\": must be in (0, 1], got 0");
  EXPECT_EQ(errorOf([&] { p.getFloat("one", 0.5f, Range::rightOpen(0, 1)); }),
            "scene.xml:3: parameter \"one\" of \"x\": must be in [0, 1), got 1");
  EXPECT_EQ(errorOf([&] { p.getFloat("one", 0.5f, Range::open(0, 1)); }),
            "scene.xml:3: parameter \"one\" of \"x\": must be in (0, 1), got 1");
  EXPECT_EQ(errorOf([&] { p.getFloat("zero", 0.5f, Range::open(0, 1)); }),
            "scene.xml:2: parameter \"zero\" of \"x\": must be in (0, 1), got 0");
}

TEST(PropertiesChecked, OneSidedFloatRangesRejectInfinityAndNaN) {
  Properties p("x");
  p.setFloat("zero", 0.0, at(2));
  p.setFloat("inf", std::numeric_limits<double>::infinity(), at(3));
  p.setFloat("nan", std::nan(""), at(4));
  EXPECT_FLOAT_EQ(p.getFloat("zero", 1.0f, Range::nonNegative()), 0.0f);
  EXPECT_EQ(errorOf([&] { p.getFloat("zero", 1.0f, Range::positive(), "bins"); }),
            "scene.xml:2: parameter \"zero\" of \"x\": must be positive and finite (bins), got 0");
  EXPECT_EQ(errorOf([&] { p.getFloat("inf", 1.0f, Range::nonNegative()); }),
            "scene.xml:3: parameter \"inf\" of \"x\": must be at least 0 and finite, got inf");
  EXPECT_EQ(errorOf([&] { p.getFloat("zero", 2.0f, Range::atLeast(1)); }),
            "scene.xml:2: parameter \"zero\" of \"x\": must be at least 1 and finite, got 0");
  EXPECT_EQ(errorOf([&] { p.getFloat("zero", 2.0f, Range::greaterThan(0.5)); }),
            "scene.xml:2: parameter \"zero\" of \"x\": must be greater than 0.5 and finite, got 0");
  EXPECT_NE(errorOf([&] { p.getFloat("nan", 1.0f, Range::finite()); }).find("scene.xml:4: "), std::string::npos);
  EXPECT_NE(errorOf([&] { p.getFloat("nan", 1.0f, Range::finite()); }).find("must be finite, got nan"),
            std::string::npos);
  EXPECT_FLOAT_EQ(p.getFloat("absent", 3.0f, Range::positive()), 3.0f);
}

TEST(PropertiesChecked, WrongTypesAreReportedBeforeTheRange) {
  Properties p("x");
  p.setString("n", "five", at(7));
  p.setInt("i", 3, at(8));
  EXPECT_EQ(errorOf([&] { p.getInt("n", 1, 0, 10); }),
            "scene.xml:7: parameter \"n\" of \"x\": expected <integer>, got <string>");
  EXPECT_EQ(errorOf([&] { p.getFloat("n", 1.0f, Range::positive()); }),
            "scene.xml:7: parameter \"n\" of \"x\": expected <float>, got <string>");
  EXPECT_FLOAT_EQ(p.getFloat("i", 1.0f, Range::closed(0, 10)), 3.0f);  // an integer where a float is expected
}

TEST(PropertiesChecked, CheckRangeOfADerivedValueNamesTheParameter) {
  Properties p("x");
  p.setFloat("width", -2.0, at(5));
  EXPECT_NO_THROW(p.checkRange("width", 0.5, Range::positive()));
  EXPECT_EQ(errorOf([&] { p.checkRange("width", -2.0 * 3.0, Range::positive()); }),
            "scene.xml:5: parameter \"width\" of \"x\": must be positive and finite, got -6");
}

namespace {
enum class Shape { Box, Tent, Gaussian };
Shape shapeOf(const Properties& p) {
  return p.getEnum("filter", Shape::Box,
                   {{"box", Shape::Box}, {"tent", Shape::Tent, "triangular"}, {"gaussian", Shape::Gaussian}});
}
}  // namespace

TEST(PropertiesChecked, EnumMatchesNamesAndDefaults) {
  Properties absent("film");
  EXPECT_EQ(shapeOf(absent), Shape::Box);
  EXPECT_EQ(absent.askedNames(), (std::vector<std::string>{"filter"}));  // asked for, for did-you-mean on unused names
  Properties p("film");
  p.setString("filter", "gaussian", at(3));
  EXPECT_EQ(shapeOf(p), Shape::Gaussian);
  EXPECT_TRUE(p.unqueried().empty());
  Properties tent("film");
  tent.setString("filter", "tent", at(3));
  EXPECT_EQ(shapeOf(tent), Shape::Tent);
}

TEST(PropertiesChecked, EnumUnknownValueListsTheChoicesWithDidYouMean) {
  Properties p("film");
  p.setString("filter", "gausian", at(4));
  EXPECT_EQ(errorOf([&] { shapeOf(p); }),
            "scene.xml:4: parameter \"filter\" of \"film\": expected \"box\", \"tent\" (triangular) or \"gaussian\", "
            "got \"gausian\" (did you mean \"gaussian\"?)");
  Properties far("film");
  far.setString("filter", "lanczos", at(6));
  EXPECT_EQ(errorOf([&] { shapeOf(far); }),
            "scene.xml:6: parameter \"filter\" of \"film\": expected \"box\", \"tent\" (triangular) or \"gaussian\", "
            "got \"lanczos\"");
  Properties wrongType("film");
  wrongType.setInt("filter", 2, at(7));
  EXPECT_EQ(errorOf([&] { shapeOf(wrongType); }),
            "scene.xml:7: parameter \"filter\" of \"film\": expected <string>, got <integer>");
}
