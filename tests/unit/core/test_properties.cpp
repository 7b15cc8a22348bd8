#include <gtest/gtest.h>

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
