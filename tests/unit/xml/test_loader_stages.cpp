// Parse stages 1-4 (XML -> nodes, directives, legacy names, references), on
// strings and temporary files; no plugins needed.
#include "loader_test_support.h"

using namespace femto;
using namespace femto::xml;
using femto::loadertest::freshDir;
using femto::loadertest::writeFile;

namespace {
ParsedScene parse(const std::string& xml, const LoadOptions& options = {}, const std::filesystem::path& dir = ".") {
  return parseString(xml, dir, options, "test.xml");
}
}  // namespace

TEST(LoaderReadXml, NodesRememberFileLineAndLineText) {
  XmlNode root = readXmlString("<scene version=\"0.5.0\">\n  <!-- c -->\n  <bsdf type=\"diffuse\">\n"
                               "    <float name=\"x\" value=\"1\"/>\n  </bsdf>\n</scene>\n",
                               "a.xml");
  EXPECT_EQ(root.tag, "scene");
  EXPECT_EQ(root.dialect, 0);
  ASSERT_EQ(root.children.size(), 1u);  // the comment is dropped
  const XmlNode& bsdf = root.children[0];
  EXPECT_EQ(bsdf.location.toString(), "a.xml:3");
  EXPECT_EQ(bsdf.lineText(), "  <bsdf type=\"diffuse\">");
  EXPECT_EQ(*bsdf.attribute("type"), "diffuse");
  EXPECT_EQ(bsdf.children[0].location.line, 4);
  EXPECT_EQ(bsdf.children[0].dialect, 0);
}

TEST(LoaderReadXml, MalformedXmlNamesTheLine) {
  EXPECT_SCENE_ERROR(readXmlString("<scene>\n  <bsdf type=\"diffuse\">\n</scene>\n", "bad.xml"), "bad.xml:2",
                     "malformed XML: an element is not closed");
  std::string message = loadertest::errorOf([] { readXmlString("<scene>\n<bsdf type=\"a\">\n</scene>\n", "bad.xml"); });
  EXPECT_NE(message.find("\n    <bsdf type=\"a\">"), std::string::npos) << message;  // the line is echoed
}

TEST(LoaderReadXml, VersionGivesTheDialect) {
  EXPECT_EQ(readXmlString("<scene version=\"3.0.0\"/>", "a").dialect, 3);
  EXPECT_EQ(readXmlString("<scene version='2.1'/>", "a").dialect, 2);
  EXPECT_EQ(readXmlString("<scene version=\"0.6.0\"/>", "a").dialect, 0);
  EXPECT_EQ(readXmlString("<scene/>", "a").dialect, UnknownDialect);
  EXPECT_EQ(parse("<scene/>").root.dialect, 3);  // a scene without version is Mitsuba 3
  EXPECT_SCENE_ERROR(readXmlString("<scene version=\"abc\"/>", "a.xml"), "a.xml:1", "expected a version");
}

TEST(LoaderExpand, DefaultsAndSubstitution) {
  auto p = parse("<scene version=\"3.0.0\">\n"
                 "  <default name=\"spp\" value=\"16\"/>\n"
                 "  <default name=\"spp\" value=\"99\"/>\n"
                 "  <sampler type=\"independent\"><integer name=\"sample_count\" value=\"$spp\"/></sampler>\n"
                 "  <integrator type=\"$spp$spp\"/>\n"
                 "</scene>");
  ASSERT_EQ(p.root.children.size(), 2u);  // <default> elements are gone
  EXPECT_EQ(*p.root.children[0].children[0].attribute("value"), "16");  // the first default wins
  EXPECT_EQ(*p.root.children[1].attribute("type"), "1616");
}

TEST(LoaderExpand, CommandLineDefinesOverrideDefaults) {
  LoadOptions options;
  options.defines["spp"] = "4";
  options.defines["only_cli"] = "x";
  auto p = parse("<scene><default name=\"spp\" value=\"16\"/>"
                 "<sampler type=\"$only_cli\"><integer name=\"sample_count\" value=\"$spp\"/></sampler></scene>",
                 options);
  EXPECT_EQ(*p.root.children[0].children[0].attribute("value"), "4");
  EXPECT_EQ(*p.root.children[0].attribute("type"), "x");
}

TEST(LoaderExpand, UnusedDefineWarnsOrFailsWhenStrict) {
  LoadOptions options;
  options.defines["spp"] = "4";
  options.defines["sp"] = "8";           // a typo: nothing refers to $sp
  options.defines["declared"] = "1";     // declared by <default> but never substituted
  const std::string xml = "<scene><default name=\"spp\" value=\"16\"/><default name=\"declared\" value=\"0\"/>"
                          "<integer name=\"n\" value=\"$spp\"/></scene>";
  auto p = parse(xml, options);  // a warning only
  EXPECT_EQ(p.expanded.unusedDefines, (std::vector<std::string>{"declared", "sp"}));
  options.strict = true;
  std::string message = loadertest::errorOf([&] { parse(xml, options); });
  EXPECT_NE(message.find("-D declared=1 was not used: the scene never refers to $declared"), std::string::npos) << message;
  options.defines.erase("sp");
  options.defines.erase("declared");
  EXPECT_NO_THROW(parse(xml, options));
}

TEST(LoaderExpand, UnusedDefineSuggestsTheScenesParameterNames) {
  LoadOptions options;
  options.strict = true;
  options.defines["sp"] = "8";  // a typo of $spp
  const std::string xml = "<scene><default name=\"width\" value=\"16\"/>"
                          "<integer name=\"n\" value=\"$spp\"/><integer name=\"w\" value=\"$width\"/></scene>";
  options.defines["spp"] = "4";
  std::string message = loadertest::errorOf([&] { parse(xml, options); });
  EXPECT_NE(message.find("-D sp=8 was not used: the scene never refers to $sp (did you mean \"spp\"?)"),
            std::string::npos)
      << message;
  // A name close to nothing the scene uses gets no hint.
  options.defines.erase("sp");
  options.defines["zzzzzz"] = "1";
  message = loadertest::errorOf([&] { parse(xml, options); });
  EXPECT_EQ(message.find("did you mean"), std::string::npos) << message;
  // A <default> that nothing substitutes is still a candidate.
  options.defines.erase("zzzzzz");
  options.defines.erase("spp");
  options.defines["widt"] = "1";
  message = loadertest::errorOf([&] { parse("<scene><default name=\"width\" value=\"1\"/></scene>", options); });
  EXPECT_NE(message.find("(did you mean \"width\"?)"), std::string::npos) << message;
}

TEST(LoaderExpand, UndefinedParameterIsAnErrorAtItsLine) {
  EXPECT_SCENE_ERROR(parse("<scene>\n\n  <integer name=\"a\" value=\"$nope\"/>\n</scene>"), "test.xml:3",
                     "undefined parameter \"$nope\"");
  // A default declared after its use does not count (document order).
  EXPECT_SCENE_ERROR(parse("<scene>\n<integer name=\"a\" value=\"$x\"/>\n<default name=\"x\" value=\"1\"/>\n</scene>"),
                     "test.xml:2", "undefined parameter \"$x\"");
}

TEST(LoaderExpand, NestedIncludesResolveAgainstTheMainSceneFolder) {
  auto dir = freshDir("includes");
  writeFile(dir / "main.xml",
            "<scene version=\"3.0.0\">\n"
            "  <default name=\"res\" value=\"32\"/>\n"
            "  <include filename=\"fragments/a.xml\"/>\n"
            "  <emitter type=\"area\" id=\"light\"/>\n"
            "</scene>\n");
  // b.xml is named relative to the MAIN folder, not to fragments/.
  writeFile(dir / "fragments/a.xml",
            "<scene version=\"3.0.0\">\n  <include filename=\"fragments/b.xml\"/>\n"
            "  <film type=\"hdrfilm\"><integer name=\"width\" value=\"$res\"/></film>\n</scene>\n");
  writeFile(dir / "fragments/b.xml", "<scene version=\"0.6.0\">\n  <bsdf type=\"diffuse\" id=\"white\">\n"
                                     "    <rgb name=\"diffuseReflectance\" value=\"1\"/>\n  </bsdf>\n</scene>\n");
  auto p = parseFile(dir / "main.xml", {});
  ASSERT_EQ(p.root.children.size(), 3u);
  EXPECT_EQ(p.root.children[0].tag, "bsdf");
  EXPECT_EQ(p.root.children[0].location.line, 2);
  EXPECT_NE(p.root.children[0].location.file.find("b.xml"), std::string::npos);
  EXPECT_EQ(p.root.children[0].dialect, 0);  // each file keeps its own dialect...
  EXPECT_EQ(*p.root.children[0].children[0].attribute("name"), "diffuse_reflectance");  // ...and is upgraded
  EXPECT_EQ(p.root.children[1].tag, "film");
  EXPECT_EQ(*p.root.children[1].children[0].attribute("value"), "32");
  EXPECT_EQ(p.root.children[2].tag, "emitter");
}

TEST(LoaderExpand, IncludeWithoutVersionTakesTheIncludersDialect) {
  auto dir = freshDir("include_dialect");
  writeFile(dir / "main.xml", "<scene version=\"0.5.0\">\n  <include filename=\"part.xml\"/>\n</scene>\n");
  writeFile(dir / "part.xml", "<bsdf type=\"diffuse\"><rgb name=\"specularReflectance\" value=\"1\"/></bsdf>\n");
  auto p = parseFile(dir / "main.xml", {});
  ASSERT_EQ(p.root.children.size(), 1u);
  EXPECT_EQ(*p.root.children[0].children[0].attribute("name"), "specular_reflectance");
}

TEST(LoaderExpand, IntegratorFileReplacesTheScenesIntegratorWhereverItWasIncluded) {
  // --integrator FILE: the scene's own integrator (here from an include, as in
  // the fog box) goes; the file's stays, after the scene's elements, seeing
  // the scene's $names; its <default> does not override the scene's.
  auto dir = freshDir("integrator_file");
  writeFile(dir / "main.xml",
            "<scene version=\"3.0.0\">\n  <default name=\"depth\" value=\"5\"/>\n  <default name=\"spp\" value=\"64\"/>\n"
            "  <include filename=\"integrator-path.xml\"/>\n  <bsdf type=\"diffuse\"/>\n</scene>\n");
  writeFile(dir / "integrator-path.xml",
            "<scene version=\"3.0.0\"><integrator type=\"path\"><integer name=\"max_depth\" value=\"$depth\"/>"
            "</integrator></scene>\n");
  writeFile(dir / "mine.xml",
            "<scene version=\"3.0.0\">\n  <default name=\"spp\" value=\"8\"/>\n"
            "  <integrator type=\"direct\"><integer name=\"max_depth\" value=\"$depth\"/><integer name=\"n\" value=\"$spp\"/>"
            "</integrator>\n</scene>\n");
  LoadOptions options;
  options.integratorFile = dir / "mine.xml";
  auto p = parseFile(dir / "main.xml", options);
  ASSERT_EQ(p.root.children.size(), 2u);
  EXPECT_EQ(p.root.children[0].tag, "bsdf");
  const XmlNode& integrator = p.root.children[1];
  EXPECT_EQ(*integrator.attribute("type"), "direct");
  EXPECT_EQ(*integrator.children[0].attribute("value"), "5");   // the scene's $depth
  EXPECT_EQ(*integrator.children[1].attribute("value"), "64");  // the scene's spp, not the file's default
  EXPECT_NE(integrator.location.toString().find("mine.xml:3"), std::string::npos) << integrator.location.toString();
  // An <integrator> root works too; a file without one, or no file, is an error naming it.
  writeFile(dir / "bare.xml", "<integrator type=\"direct\"/>\n");
  options.integratorFile = dir / "bare.xml";
  EXPECT_EQ(*parseFile(dir / "main.xml", options).root.children[1].attribute("type"), "direct");
  writeFile(dir / "none.xml", "<scene version=\"3.0.0\"><bsdf type=\"diffuse\"/></scene>\n");
  options.integratorFile = dir / "none.xml";
  std::string message = loadertest::errorOf([&] { parseFile(dir / "main.xml", options); });
  EXPECT_NE(message.find("none.xml\" holds no <integrator> element"), std::string::npos) << message;
  options.integratorFile = dir / "missing.xml";
  message = loadertest::errorOf([&] { parseFile(dir / "main.xml", options); });
  EXPECT_NE(message.find("--integrator: no such file"), std::string::npos) << message;
}

TEST(LoaderExpand, MissingIncludeIsAnErrorAtItsLine) {
  auto dir = freshDir("include_missing");
  EXPECT_SCENE_ERROR(parse("<scene>\n  <include filename=\"nothere.xml\"/>\n</scene>", {}, dir), "test.xml:2",
                     "included file \"nothere.xml\" not found");
}

TEST(LoaderExpand, IncludeCycleIsAnError) {
  auto dir = freshDir("include_cycle");
  writeFile(dir / "main.xml", "<scene>\n  <include filename=\"a.xml\"/>\n</scene>\n");
  writeFile(dir / "a.xml", "<scene>\n\n  <include filename=\"main.xml\"/>\n</scene>\n");
  std::string message = loadertest::errorOf([&] { parseFile(dir / "main.xml", {}); });
  EXPECT_NE(message.find("a.xml:3: file \"main.xml\" includes itself (include cycle)"), std::string::npos) << message;
}

TEST(LoaderExpand, PathAddsASearchDirectory) {
  auto dir = freshDir("path");
  writeFile(dir / "assets/mesh.obj", "");
  auto p = parse("<scene><path value=\"assets\"/></scene>", {}, dir);
  auto found = p.expanded.resolver.resolve("mesh.obj");
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->filename(), "mesh.obj");
  EXPECT_TRUE(found->is_absolute());
  EXPECT_FALSE(p.expanded.resolver.resolve("other.obj").has_value());
}

TEST(LoaderExpand, AliasLetsRefsUseAnotherName) {
  auto p = parse("<scene><bsdf type=\"diffuse\" id=\"a\"/><alias id=\"a\" as=\"b\"/>"
                 "<shape type=\"sphere\"><ref id=\"b\"/></shape></scene>");
  ASSERT_EQ(p.root.children.size(), 2u);
  EXPECT_EQ(p.root.children[1].children[0].target, &p.root.children[0]);
}

TEST(LoaderUpgrade, CamelToSnake) {
  EXPECT_EQ(camelToSnake("toWorld"), "to_world");
  EXPECT_EQ(camelToSnake("intIOR"), "int_ior");
  EXPECT_EQ(camelToSnake("sampleCount"), "sample_count");
  EXPECT_EQ(camelToSnake("cropOffsetX"), "crop_offset_x");
  EXPECT_EQ(camelToSnake("maxDepth"), "max_depth");
  EXPECT_EQ(camelToSnake("sigmaS"), "sigma_s");
  EXPECT_EQ(camelToSnake("uv2Scale"), "uv2_scale");
  EXPECT_EQ(camelToSnake("already_snake"), "already_snake");
  EXPECT_EQ(camelToSnake("IOR"), "ior");
  EXPECT_EQ(camelToSnake("B"), "B");  // mitchell's parameters, the same in both dialects
}

TEST(LoaderUpgrade, OnlyLegacyDialectIsRenamed) {
  auto legacy = parse("<scene version=\"0.6.0\"><shape type=\"disk\"><boolean name=\"flipNormals\" value=\"true\"/>"
                      "</shape></scene>");
  EXPECT_EQ(*legacy.root.children[0].children[0].attribute("name"), "flip_normals");
  auto modern = parse("<scene version=\"3.0.0\"><shape type=\"disk\"><boolean name=\"flipNormals\" value=\"true\"/>"
                      "</shape></scene>");
  EXPECT_EQ(*modern.root.children[0].children[0].attribute("name"), "flipNormals");
}

TEST(LoaderRefs, DuplicateIdIsAnError) {
  EXPECT_SCENE_ERROR(parse("<scene>\n  <bsdf type=\"diffuse\" id=\"a\"/>\n  <bsdf type=\"conductor\" id=\"a\"/>\n"
                           "</scene>"),
                     "test.xml:3", "duplicate id \"a\" (first declared at test.xml:2)");
}

TEST(LoaderRefs, UnresolvedRefIsAnErrorWithCloseIds) {
  EXPECT_SCENE_ERROR(parse("<scene>\n  <bsdf type=\"diffuse\" id=\"white\"/>\n  <shape type=\"sphere\">\n"
                           "    <ref id=\"whte\"/>\n  </shape>\n</scene>"),
                     "test.xml:4", "unresolved reference to id \"whte\" (did you mean \"white\"?)");
}

TEST(LoaderRefs, ReferenceCyclesAreErrors) {
  // An object that refers to itself, even when nothing else uses it.
  EXPECT_SCENE_ERROR(parse("<scene>\n  <texture type=\"t\" id=\"a\">\n    <ref id=\"a\"/>\n  </texture>\n</scene>"),
                     "test.xml:3", "reference to \"a\" makes a cycle");
  // A cycle through a nested object: a -> (nested b) -> c -> a.
  EXPECT_SCENE_ERROR(parse("<scene>\n<texture type=\"t\" id=\"a\"><texture type=\"t\" id=\"b\">"
                           "<ref id=\"c\"/></texture></texture>\n<texture type=\"t\" id=\"c\">\n"
                           "  <ref id=\"a\"/>\n</texture>\n</scene>"),
                     "test.xml:4", "reference to \"a\" makes a cycle");
  // Sharing is not a cycle.
  EXPECT_NO_THROW(parse("<scene><texture type=\"t\" id=\"a\"/><bsdf type=\"x\"><ref id=\"a\"/><ref id=\"a\" "
                        "name=\"b\"/></bsdf></scene>"));
}

TEST(LoaderRefs, ForwardReferencesResolve) {
  auto p = parse("<scene><shape type=\"sphere\"><ref id=\"later\" name=\"interior\"/></shape>"
                 "<medium type=\"homogeneous\" id=\"later\"/></scene>");
  EXPECT_EQ(p.root.children[0].children[0].target, &p.root.children[1]);
  EXPECT_EQ(p.index.referenced.count("later"), 1u);
}

TEST(LoaderErrors, EchoTheOffendingLineIndented) {
  std::string message = loadertest::errorOf([] { parse("<scene>\n  <float name=\"x\" value=\"$undefined\"/>\n</scene>"); });
  auto newline = message.find('\n');
  ASSERT_NE(newline, std::string::npos) << message;
  EXPECT_EQ(message.substr(newline), "\n    <float name=\"x\" value=\"$undefined\"/>");
}

TEST(LoaderErrors, LongLinesAreShortenedInTheEcho) {
  std::string longValue(400, '1');
  std::string message = loadertest::errorOf([&] { parse("<scene>\n<x a=\"" + longValue + "\" b=\"$undefined\"/>\n</scene>"); });
  auto newline = message.find('\n');
  ASSERT_NE(newline, std::string::npos) << message;
  EXPECT_EQ(message.size() - newline, 1 + 4 + 160 + 4) << message;  // "\n", indent, 160 characters, " ..."
  EXPECT_EQ(message.substr(message.size() - 4), " ...");
}

// Every real scene in the shared corpus passes stages 1-4.
TEST(LoaderRealScenes, StagesAcceptTheSharedCorpus) {
  std::filesystem::path corpus = std::filesystem::path(FEMTO_SOURCE_DIR) / "../shared/scenes";
  if (!std::filesystem::exists(corpus)) corpus = "/work/shared/scenes";
  if (!std::filesystem::exists(corpus)) GTEST_SKIP() << "no shared scene corpus";
  const char* scenes[] = {
      "lajolla-veach-mis-0.4/mi.xml",
      "lajolla-vol-cbox-fog-0.5/vol_cbox.xml",
      "m3data-cbox-rgb-includes/cbox-rgb.xml",
      "m3data-media-homog-arealight/tests/scenes/participating_media/test_homo_area_light_volpath.xml",
      "mitransient-cbox-diffuse/cbox_diffuse.xml",
      "mitsuba06-test-bidir-medium-disks/test_bidir_2.xml",
  };
  int parsed = 0;
  for (const char* scene : scenes) {
    auto file = corpus / scene;
    if (!std::filesystem::exists(file)) continue;
    SCOPED_TRACE(scene);
    EXPECT_NO_THROW(parseFile(file, {}));
    ++parsed;
  }
  EXPECT_GT(parsed, 0);
}

TEST(LoaderRealScenes, IncludedFragmentsReferToObjectsDeclaredLater) {
  auto file = std::filesystem::path("/work/shared/scenes/m3data-cbox-rgb-includes/cbox-rgb.xml");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no shared scene corpus";
  auto p = parseFile(file, {});
  EXPECT_EQ(p.index.referenced.count("area-emitter"), 1u);
  EXPECT_EQ(p.index.byId.count("white"), 1u);
}
