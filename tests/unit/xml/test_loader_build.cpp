// Stage 5 (object creation) with a factory double: nesting, references,
// overrides, file names, unused parameters, and both dialects.
#include <sstream>

#include "loader_test_support.h"

using namespace femto;
using namespace femto::xml;
using femto::loadertest::buildRecorded;
using femto::loadertest::freshDir;
using femto::loadertest::recorded;
using femto::loadertest::RecordingFactory;
using femto::loadertest::writeFile;

namespace {

/// Every parameter as "name:type=value" lines, nested objects recursively.
std::string describe(const Properties& p, const std::string& indent = "") {
  std::ostringstream os;
  os << indent << p.pluginName() << " id=" << p.id() << "\n";
  for (const auto& name : p.names()) {
    os << indent << name << ":" << Properties::typeName(p.type(name)) << "=";
    switch (p.type(name)) {
      case Properties::Type::Bool: os << p.getBool(name); break;
      case Properties::Type::Integer: os << p.getInt(name); break;
      case Properties::Type::Float: os << p.getFloat(name); break;
      case Properties::Type::String: os << p.getString(name); break;
      case Properties::Type::Point:
      case Properties::Type::Vector: os << p.getVector(name); break;
      case Properties::Type::Color: os << p.getColor(name); break;
      case Properties::Type::Transform: os << p.getTransform(name).matrix(); break;
      case Properties::Type::Object: os << "\n" << describe(recorded(p.getObject(name)).props, indent + "  "); break;
    }
    os << "\n";
  }
  return os.str();
}

}  // namespace

TEST(LoaderBuild, NestedObjectsAreNamedOrNumbered) {
  auto scene = buildRecorded("<scene>\n<shape type=\"sphere\">\n  <bsdf type=\"diffuse\"/>\n"
                             "  <medium type=\"homogeneous\" name=\"interior\"/>\n  <emitter type=\"area\"/>\n"
                             "</shape>\n</scene>");
  EXPECT_EQ(scene->props.pluginName(), "scene");
  EXPECT_EQ(scene->kind(), ObjectKind::Scene);
  const auto& shape = recorded(scene->props.getObject("_arg_0"));
  EXPECT_EQ(shape.kind(), ObjectKind::Shape);
  EXPECT_EQ(shape.props.names(), (std::vector<std::string>{"_arg_0", "interior", "_arg_1"}));
  EXPECT_EQ(shape.props.getObject("_arg_0")->kind(), ObjectKind::BSDF);
  EXPECT_EQ(shape.props.getObject("interior")->kind(), ObjectKind::Medium);
  EXPECT_EQ(shape.props.getObject("_arg_1")->kind(), ObjectKind::Emitter);
  EXPECT_EQ(shape.props.location().toString(), "test.xml:2");
}

TEST(LoaderBuild, ReferencedObjectsAreBuiltOnceAndOwnedByReferrers) {
  RecordingFactory factory;
  int bsdfs = 0;
  factory.onCreate = [&](const Properties& p) { bsdfs += p.pluginName() == "diffuse"; };
  auto scene = buildRecorded("<scene><shape type=\"a\"><ref id=\"white\"/></shape>"
                             "<shape type=\"b\"><ref id=\"white\" name=\"bsdf\"/></shape>"
                             "<bsdf type=\"diffuse\" id=\"white\"/><bsdf type=\"diffuse\" id=\"unused\"/></scene>",
                             {}, &factory);
  EXPECT_EQ(bsdfs, 2);
  auto a = recorded(scene->props.getObject("_arg_0")).props.getObject("_arg_0");
  auto b = recorded(scene->props.getObject("_arg_1")).props.getObject("bsdf");
  EXPECT_EQ(a, b);  // the same object
  EXPECT_EQ(a->id(), "white");
  // "white" belongs to the shapes; "unused" (never referenced) stays a child of the scene.
  EXPECT_EQ(scene->props.names(), (std::vector<std::string>{"_arg_0", "_arg_1", "_arg_2"}));
  EXPECT_EQ(scene->props.getObject("_arg_2")->id(), "unused");
}

TEST(LoaderBuild, UnsupportedTagIsAnError) {
  EXPECT_SCENE_ERROR(buildRecorded("<scene>\n  <bsdf type=\"diffuse\">\n    <colour name=\"x\" value=\"1\"/>\n"
                                   "  </bsdf>\n</scene>"),
                     "test.xml:3", "unsupported tag <colour>");
  EXPECT_SCENE_ERROR(buildRecorded("<scene>\n  <scene/>\n</scene>"), "test.xml:2", "a <scene> cannot be nested");
  EXPECT_SCENE_ERROR(buildRecorded("<scene>\n  <bsdf/>\n</scene>"), "test.xml:2", "<bsdf> needs a type=");
}

TEST(LoaderBuild, UnusedParameterWarnsOrFailsWhenStrict) {
  RecordingFactory factory;
  factory.reads["diffuse"] = {"reflectance"};
  const std::string xml =
      "<scene>\n  <bsdf type=\"diffuse\">\n    <rgb name=\"reflectanse\" value=\"0.5\"/>\n  </bsdf>\n</scene>";
  EXPECT_NO_THROW(buildRecorded(xml, {}, &factory));  // a warning only
  LoadOptions strict;
  strict.strict = true;
  std::string message = loadertest::errorOf([&] { buildRecorded(xml, strict, &factory); });
  EXPECT_EQ(message,
            "test.xml:3: parameter \"reflectanse\" of \"diffuse\" was not used (did you mean \"reflectance\"?)\n"
            "    <rgb name=\"reflectanse\" value=\"0.5\"/>");
}

TEST(LoaderBuild, UnusedNestedObjectIsReportedAsWritten) {
  // An unnamed child is keyed "_arg_0" inside the loader; the message names
  // what the file says: tag, type, id and the line it is declared on.
  RecordingFactory factory;
  factory.reads["point"] = {"intensity"};
  LoadOptions strict;
  strict.strict = true;
  std::string nested = loadertest::errorOf([&] {
    buildRecorded("<scene>\n  <emitter type=\"point\">\n    <medium type=\"homogeneous\" id=\"fog\"/>\n"
                  "  </emitter>\n</scene>",
                  strict, &factory);
  });
  EXPECT_EQ(nested,
            "test.xml:3: nested <medium type=\"homogeneous\" id=\"fog\"> (line 3) of \"point\" was not used\n"
            "    <medium type=\"homogeneous\" id=\"fog\"/>");
  std::string referenced = loadertest::errorOf([&] {
    buildRecorded("<scene>\n  <medium type=\"homogeneous\" id=\"fog\"/>\n  <emitter type=\"point\">\n"
                  "    <ref id=\"fog\"/>\n  </emitter>\n</scene>",
                  strict, &factory);
  });
  EXPECT_EQ(referenced,
            "test.xml:4: referenced <medium type=\"homogeneous\" id=\"fog\"> (line 2) of \"point\" was not used\n"
            "    <ref id=\"fog\"/>");
  // Without an id the tag and type alone; never the internal key, nor a "did you mean".
  std::string anonymous = loadertest::errorOf([&] {
    buildRecorded("<scene>\n  <emitter type=\"point\">\n    <rfilter type=\"box\"/>\n  </emitter>\n</scene>", strict,
                  &factory);
  });
  EXPECT_EQ(anonymous.rfind("test.xml:3: nested <rfilter type=\"box\"> (line 3) of \"point\" was not used\n", 0), 0u)
      << anonymous;
  for (const auto& message : {nested, referenced, anonymous}) EXPECT_EQ(message.find("_arg_"), std::string::npos);
}

TEST(LoaderBuild, ErrorsAboutAnUnnamedChildUseItsLabel) {
  Properties props("point");
  props.setObject("_arg_0", std::make_shared<loadertest::RecordedObject>(ObjectKind::Medium, Properties("homogeneous")),
                  SourceLocation{"scene.xml", 7}, "nested <medium type=\"homogeneous\"> (line 7)");
  EXPECT_EQ(props.describe("_arg_0"), "nested <medium type=\"homogeneous\"> (line 7)");
  EXPECT_EQ(props.describe("intensity"), "parameter \"intensity\"");
  std::string raised = loadertest::errorOf([&] { props.raise("_arg_0", "is not wanted here"); });
  EXPECT_EQ(raised, "scene.xml:7: nested <medium type=\"homogeneous\"> (line 7) of \"point\": is not wanted here");
  std::string wrongType = loadertest::errorOf([&] { props.getFloat("_arg_0"); });
  EXPECT_EQ(wrongType.find("_arg_"), std::string::npos) << wrongType;
}

TEST(LoaderBuild, ResolutionAndSampleCountOverrides) {
  LoadOptions options;
  options.resolution = Point2i(64, 48);
  options.sampleCount = 8;
  auto sensor = buildRecorded("<sensor type=\"perspective\"><film type=\"hdrfilm\">"
                              "<integer name=\"width\" value=\"512\"/></film>"
                              "<sampler type=\"independent\"/></sensor>",
                              options);
  const auto& film = recorded(sensor->props.getObject("_arg_0")).props;
  EXPECT_EQ(film.getInt("width"), 64);
  EXPECT_EQ(film.getInt("height"), 48);  // created although absent
  const auto& sampler = recorded(sensor->props.getObject("_arg_1")).props;
  EXPECT_EQ(sampler.getInt("sample_count"), 8);
  // Without overrides the scene's values stay.
  auto plain = buildRecorded("<film type=\"hdrfilm\"><integer name=\"width\" value=\"512\"/></film>");
  EXPECT_EQ(plain->props.getInt("width"), 512);
  EXPECT_FALSE(plain->props.has("height"));
}

TEST(LoaderBuild, FilenamesResolveToAbsolutePaths) {
  auto dir = freshDir("filenames");
  writeFile(dir / "meshes/a.obj", "");
  writeFile(dir / "extra/b.obj", "");
  auto scene = buildRecorded("<scene><path value=\"extra\"/>"
                             "<shape type=\"obj\"><string name=\"filename\" value=\"meshes/a.obj\"/></shape>"
                             "<shape type=\"obj\"><string name=\"filename\" value=\"b.obj\"/></shape></scene>",
                             {}, nullptr, dir);
  auto a = recorded(scene->props.getObject("_arg_0")).props.getString("filename");
  auto b = recorded(scene->props.getObject("_arg_1")).props.getString("filename");
  EXPECT_EQ(std::filesystem::path(a), std::filesystem::absolute(dir / "meshes/a.obj").lexically_normal());
  EXPECT_EQ(std::filesystem::path(b), std::filesystem::absolute(dir / "extra/b.obj").lexically_normal());
}

TEST(LoaderBuild, MissingFileIsAnErrorAtItsLine) {
  auto dir = freshDir("missing_file");
  EXPECT_SCENE_ERROR(buildRecorded("<scene>\n<shape type=\"obj\">\n  <string name=\"filename\" value=\"gone.obj\"/>\n"
                                   "</shape>\n</scene>",
                                   {}, nullptr, dir),
                     "test.xml:3", "file \"gone.obj\" not found");
}

TEST(LoaderBuild, PluginConstructorErrorsGetTheLineEchoed) {
  RecordingFactory factory;
  factory.onCreate = [](const Properties& p) {
    if (p.has("radius") && p.getFloat("radius") < 0) p.raise("radius", "must be positive");
  };
  std::string message = loadertest::errorOf([&] {
    buildRecorded("<scene>\n<shape type=\"sphere\">\n  <float name=\"radius\" value=\"-1\"/>\n</shape>\n</scene>", {},
                  &factory);
  });
  EXPECT_EQ(message, "test.xml:3: parameter \"radius\" of \"sphere\": must be positive\n"
                     "    <float name=\"radius\" value=\"-1\"/>");
  // An error without a location is placed at the object.
  factory.onCreate = [](const Properties&) { throw Error("boom"); };
  EXPECT_SCENE_ERROR(buildRecorded("<scene>\n<shape type=\"sphere\"/>\n</scene>", {}, &factory), "test.xml:2", "boom");
}

TEST(LoaderBuild, BothDialectsGiveIdenticalProperties) {
  const std::string legacy = R"(<scene version="0.6.0">
  <sensor type="perspective">
    <string name="fovAxis" value="smaller"/>
    <transform name="toWorld">
      <lookAt origin="278, 273, -800" target="278, 273, -799" up="0, 1, 0"/>
    </transform>
    <sampler type="independent"><integer name="sampleCount" value="64"/></sampler>
    <film type="hdrfilm"><integer name="cropOffsetX" value="16"/><boolean name="banner" value="false"/></film>
  </sensor>
  <shape type="obj" id="s">
    <bsdf type="roughplastic">
      <float name="intIOR" value="1.5"/>
      <rgb name="diffuseReflectance" value="0.1 0.2 0.3"/>
    </bsdf>
    <point name="center" x="1" y="2" z="3"/>
  </shape>
</scene>)";
  const std::string modern = R"(<scene version="3.0.0">
  <sensor type="perspective">
    <string name="fov_axis" value="smaller"/>
    <transform name="to_world">
      <lookat origin="278, 273, -800" target="278, 273, -799" up="0, 1, 0"/>
    </transform>
    <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
    <film type="hdrfilm"><integer name="crop_offset_x" value="16"/><boolean name="banner" value="false"/></film>
  </sensor>
  <shape type="obj" id="s">
    <bsdf type="roughplastic">
      <float name="int_ior" value="1.5"/>
      <rgb name="diffuse_reflectance" value="0.1, 0.2, 0.3"/>
    </bsdf>
    <point name="center" value="1, 2, 3"/>
  </shape>
</scene>)";
  std::string a = describe(buildRecorded(legacy)->props);
  std::string b = describe(buildRecorded(modern)->props);
  EXPECT_EQ(a, b);
  EXPECT_NE(a.find("int_ior:float=1.5"), std::string::npos) << a;
  EXPECT_NE(a.find("sample_count:integer=64"), std::string::npos) << a;
}

TEST(LoaderRealScenes, SharedCorpusBuildsWithTheDouble) {
  // Stage 5 on real files: every value parses and every file name exists
  // (the scenes whose meshes ship with them).
  const char* scenes[] = {
      "/work/shared/scenes/lajolla-vol-cbox-fog-0.5/vol_cbox.xml",
      "/work/shared/scenes/m3data-cbox-rgb-includes/cbox-rgb.xml",
      "/work/shared/scenes/mitransient-cbox-diffuse/cbox_diffuse.xml",
      "/work/shared/scenes/mitsuba06-test-bidir-medium-disks/test_bidir_2.xml",
      "/work/shared/scenes/lajolla-veach-mis-0.4/mi.xml",
  };
  int built = 0;
  for (const char* scene : scenes) {
    if (!std::filesystem::exists(scene)) continue;
    SCOPED_TRACE(scene);
    RecordingFactory factory;
    LoadOptions strict;
    strict.strict = true;
    EXPECT_NO_THROW(xml::buildObject(parseFile(scene, strict), strict, factory));
    ++built;
  }
  if (built == 0) GTEST_SKIP() << "no shared scene corpus";
}

TEST(LoaderRealScenes, LegacySpectraBecomeRgb) {
  const char* scene = "/work/shared/scenes/lajolla-vol-cbox-fog-0.5/vol_cbox.xml";
  if (!std::filesystem::exists(scene)) GTEST_SKIP() << "no shared scene corpus";
  RecordingFactory factory;
  auto root = recorded(xml::buildObject(parseFile(scene, {}), {}, factory));
  // The light's radiance 400:0, 500:80, 600:156, 700:184 averages to 40 / 118 / 170 per band.
  bool found = false;
  for (const auto& name : root.props.names()) {
    const auto& shape = recorded(root.props.getObject(name));
    if (shape.kind() != ObjectKind::Shape) continue;
    for (const auto& child : shape.props.names()) {
      if (shape.props.type(child) != Properties::Type::Object) continue;
      const auto& obj = recorded(shape.props.getObject(child));
      if (obj.kind() != ObjectKind::Emitter) continue;
      Color3f radiance = obj.props.getColor("radiance");
      EXPECT_NEAR(radiance.b, 40.0f, 1e-3);
      EXPECT_NEAR(radiance.g, 118.0f, 1e-3);
      EXPECT_NEAR(radiance.r, 170.0f, 1e-3);
      found = true;
    }
  }
  EXPECT_TRUE(found);
}
