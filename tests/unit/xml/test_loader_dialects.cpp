// Names and spellings of other renderers' scenes (issue 12): Python-written
// booleans, mitransient's and Mitsuba 2's transient film and integrator
// names. Each mapping: the parameter lands where femto reads it, and a wrong
// value names file:line.
#include <femto/render/integrator.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <femto/film/transient_film.h>
#include <femto/xml/loader.h>

#include "loader_test_support.h"

using namespace femto;
using femto::loadertest::buildRecorded;

namespace {
Properties propsOf(const std::string& body) {
  return buildRecorded("<bsdf type=\"test\">\n" + body + "\n</bsdf>")->props;
}
}  // namespace

TEST(LoaderDialects, BooleansInAnyCaseAsMitsuba3ReadsThem) {
  auto p = propsOf("<boolean name=\"a\" value=\"True\"/><boolean name=\"b\" value=\"False\"/>"
                   "<boolean name=\"c\" value=\"TRUE\"/><boolean name=\"d\" value=\" false \"/>");
  EXPECT_TRUE(p.getBool("a"));
  EXPECT_FALSE(p.getBool("b"));
  EXPECT_TRUE(p.getBool("c"));
  EXPECT_FALSE(p.getBool("d"));
  EXPECT_SCENE_ERROR(propsOf("\n<boolean name=\"b\" value=\"Yes\"/>"), "test.xml:3", "got 'Yes'");
  EXPECT_SCENE_ERROR(propsOf("<boolean name=\"b\" value=\"1\"/>"), "test.xml:2", "expected \"true\" or \"false\"");
}

// ---- Transient films and integrators under mitransient's and Mitsuba 2's names ----

namespace {

std::shared_ptr<Scene> loadStrict(const std::string& xml) {
  LoadOptions options;
  options.strict = true;
  return loadSceneFromString(xml, ".", options, "dialect.xml");
}

/// A scene with the given <integrator> and <film> (a plane and a point light).
std::string sceneWith(const std::string& integrator, const std::string& film, const std::string& version = "3.0.0") {
  return "<scene version=\"" + version + "\">\n" + integrator + "\n<sensor type=\"perspective\">\n" + film +
         "\n</sensor>\n<emitter type=\"point\"><point name=\"position\" x=\"0\" y=\"0\" z=\"1\"/></emitter>\n"
         "<shape type=\"rectangle\"/>\n</scene>";
}

const TransientFilm& transientFilmOf(const Scene& scene) {
  auto* film = dynamic_cast<const TransientFilm*>(&scene.sensor().film());
  if (!film) throw Error("the scene's film is not a transient film");
  return *film;
}

const std::string TransientPath = "<integrator type=\"transient_path\"/>";

}  // namespace

TEST(LoaderDialects, TransientHdrFilmTakesMitransientsDefaultWindow) {
  auto scene = loadStrict(sceneWith(TransientPath, "<film type=\"transient_hdr_film\"><rfilter type=\"box\"/></film>"));
  const TimeGrid& grid = transientFilmOf(*scene).timeGrid();
  EXPECT_EQ(grid.bins, 2048);
  EXPECT_DOUBLE_EQ(grid.binWidth, double(0.003f));
  EXPECT_EQ(grid.start, 0.0);
  // femto's own film keeps requiring its window.
  EXPECT_SCENE_ERROR(loadStrict(sceneWith(TransientPath, "<film type=\"transient\">\n<integer name=\"temporal_bins\" "
                                                          "value=\"4\"/></film>")),
                     "dialect.xml:4", "missing parameter \"bin_width_opl\"");
}

TEST(LoaderDialects, StreakHdrFilmMapsTimeExposureAndOffset) {
  auto scene = loadStrict(sceneWith("<integrator type=\"transientpath\"/>",
                                    "<film type=\"streakhdrfilm\"><integer name=\"time\" value=\"64\"/>"
                                    "<float name=\"exposure_time\" value=\"0.25\"/><float name=\"time_offset\" value=\"3\"/>"
                                    "<boolean name=\"high_quality_edges\" value=\"true\"/>"
                                    "<string name=\"component_format\" value=\"float32\"/>"
                                    "<rfilter type=\"box\"/></film>",
                                    "2.0.0"));
  const TransientFilm& film = transientFilmOf(*scene);
  EXPECT_EQ(film.timeGrid().bins, 64);
  EXPECT_DOUBLE_EQ(film.timeGrid().binWidth, 0.25);
  EXPECT_DOUBLE_EQ(film.timeGrid().start, 3.0);
  EXPECT_EQ(film.timeFilter().type(), TimeFilter::Type::Box);
  // Mitsuba 2's streak film defaults: 1000 bins of 1 from 0.
  auto defaults = loadStrict(sceneWith(TransientPath, "<film type=\"streakhdrfilm\"/>", "2.0.0"));
  EXPECT_EQ(transientFilmOf(*defaults).timeGrid().bins, 1000);
  EXPECT_DOUBLE_EQ(transientFilmOf(*defaults).timeGrid().binWidth, 1.0);
  // The newer names work too; both spellings of one parameter are refused at the line.
  auto newer = loadStrict(sceneWith(TransientPath, "<film type=\"streakhdrfilm\"><integer name=\"num_bins\" value=\"8\"/>"
                                                    "<float name=\"bin_width_opl\" value=\"0.5\"/></film>", "2.0.0"));
  EXPECT_EQ(transientFilmOf(*newer).timeGrid().bins, 8);
  EXPECT_SCENE_ERROR(loadStrict(sceneWith(TransientPath, "<film type=\"streakhdrfilm\">\n<integer name=\"time\" value=\"8\"/>\n"
                                                          "<integer name=\"num_bins\" value=\"8\"/></film>", "2.0.0")),
                     "dialect.xml:6", "\"num_bins\" and \"time\" are one parameter");
  EXPECT_SCENE_ERROR(loadStrict(sceneWith(TransientPath, "<film type=\"streakhdrfilm\">\n<float name=\"exposure_time\" value=\"-1\"/>"
                                                          "</film>", "2.0.0")),
                     "dialect.xml:5", "exposure_time");
}

TEST(LoaderDialects, StreakHdrFilmTimeFilterIsTheRfilterNamedTfilter) {
  auto film = [](const std::string& tfilter) {
    return sceneWith(TransientPath, "<film type=\"streakhdrfilm\"><integer name=\"time\" value=\"16\"/><rfilter type=\"box\"/>\n" +
                                         tfilter + "</film>", "2.0.0");
  };
  auto gaussian = loadStrict(film("<rfilter name=\"tfilter\" type=\"gaussian\"><float name=\"stddev\" value=\"1.5\"/></rfilter>"));
  EXPECT_EQ(transientFilmOf(*gaussian).timeFilter().type(), TimeFilter::Type::Gaussian);
  EXPECT_FLOAT_EQ(float(transientFilmOf(*gaussian).timeFilter().width()), 1.5f);
  EXPECT_EQ(transientFilmOf(*gaussian).filter()->radius(), 0.5f) << "the pixel filter stays the box";
  auto tent = loadStrict(film("<rfilter name=\"tfilter\" type=\"tent\"><float name=\"radius\" value=\"2\"/></rfilter>"));
  EXPECT_EQ(transientFilmOf(*tent).timeFilter().type(), TimeFilter::Type::Tent);
  EXPECT_FLOAT_EQ(float(transientFilmOf(*tent).timeFilter().width()), 2.0f);
  auto box = loadStrict(film("<rfilter name=\"tfilter\" type=\"box\"/>"));
  EXPECT_EQ(transientFilmOf(*box).timeFilter().type(), TimeFilter::Type::Box);
  EXPECT_SCENE_ERROR(loadStrict(film("<rfilter name=\"tfilter\" type=\"box\"><float name=\"radius\" value=\"2\"/></rfilter>")),
                     "dialect.xml:5", "a box of radius 2 bins is not supported");
}

TEST(LoaderDialects, MitransientTemporalFilterBecomesTheFilmsTimeFilter) {
  const std::string film =
      "<film type=\"transient_hdr_film\"><integer name=\"temporal_bins\" value=\"16\"/><rfilter type=\"box\"/></film>";
  auto gaussian = loadStrict(sceneWith("<integrator type=\"transient_path\"><string name=\"temporal_filter\" value=\"gaussian\"/>"
                                       "<float name=\"gaussian_stddev\" value=\"3\"/></integrator>", film));
  EXPECT_EQ(transientFilmOf(*gaussian).timeFilter().type(), TimeFilter::Type::Gaussian);
  EXPECT_FLOAT_EQ(float(transientFilmOf(*gaussian).timeFilter().width()), 3.0f);
  // mitransient's default standard deviation is 2 bins; a narrow one is kept
  // (femto integrates the gaussian over each bin, exact however narrow).
  auto byDefault = loadStrict(sceneWith("<integrator type=\"transient_prbvolpath\"><string name=\"temporal_filter\" "
                                        "value=\"gaussian\"/></integrator>", film));
  EXPECT_FLOAT_EQ(float(transientFilmOf(*byDefault).timeFilter().width()), 2.0f);
  auto narrow = loadStrict(sceneWith("<integrator type=\"transient_path\"><string name=\"temporal_filter\" value=\"gaussian\"/>"
                                     "<float name=\"gaussian_stddev\" value=\"0.1\"/></integrator>", film));
  EXPECT_FLOAT_EQ(float(transientFilmOf(*narrow).timeFilter().width()), 0.1f);
  // "" leaves the film's own filter; "box" is the box.
  auto own = loadStrict(sceneWith("<integrator type=\"transient_path\"><string name=\"temporal_filter\" value=\"\"/></integrator>",
                                  "<film type=\"transient\"><integer name=\"temporal_bins\" value=\"4\"/><float name=\"bin_width_opl\" "
                                  "value=\"1\"/><string name=\"time_filter\" value=\"tent\"/></film>"));
  EXPECT_EQ(transientFilmOf(*own).timeFilter().type(), TimeFilter::Type::Tent);
  // Wrong values and a filter given twice name the line.
  EXPECT_SCENE_ERROR(loadStrict(sceneWith("<integrator type=\"transient_path\">\n<string name=\"temporal_filter\" value=\"tent\"/>"
                                          "</integrator>", film)),
                     "dialect.xml:3", "expected \"box\", \"gaussian\" or \"\"");
  EXPECT_SCENE_ERROR(loadStrict(sceneWith("<integrator type=\"transient_path\"><string name=\"temporal_filter\" value=\"gaussian\"/>"
                                          "\n<float name=\"gaussian_stddev\" value=\"-1\"/></integrator>", film)),
                     "dialect.xml:3", "gaussian_stddev");
  EXPECT_SCENE_ERROR(loadStrict(sceneWith("<integrator type=\"transient_path\">\n<string name=\"temporal_filter\" value=\"gaussian\"/>"
                                          "</integrator>",
                                          "<film type=\"transient\"><integer name=\"temporal_bins\" value=\"4\"/><float name=\"bin_width_opl\" "
                                          "value=\"1\"/><string name=\"time_filter\" value=\"tent\"/></film>")),
                     "dialect.xml:3", "differs from the time filter the film gives at dialect.xml:5");
}

TEST(LoaderDialects, MitransientIntegratorNamesAndParameters) {
  const std::string film =
      "<film type=\"transient_hdr_film\"><integer name=\"temporal_bins\" value=\"16\"/><rfilter type=\"box\"/></film>";
  auto prb = loadStrict(sceneWith("<integrator type=\"transient_prbvolpath\"><boolean name=\"camera_unwarp\" value=\"True\"/>"
                                  "<boolean name=\"discard_direct_light\" value=\"False\"/>"
                                  "<integer name=\"rr_depth\" value=\"3\"/></integrator>", film));
  std::string described = prb->integrator().toString();
  EXPECT_NE(described.find("max_depth=6"), std::string::npos) << described << " (mitransient's default depth)";
  EXPECT_NE(described.find("rr_depth=3"), std::string::npos) << described;
  EXPECT_NE(described.find("observer_time=false"), std::string::npos) << described;
  auto old = loadStrict(sceneWith("<integrator type=\"transientpath\"/>", film, "2.0.0"));
  EXPECT_NE(old->integrator().toString().find("max_depth=-1"), std::string::npos) << old->integrator().toString();
  EXPECT_SCENE_ERROR(loadStrict(sceneWith("<integrator type=\"transient_prbvolpath\">\n<integer name=\"max_depth\" value=\"-3\"/>"
                                          "</integrator>", film)),
                     "dialect.xml:3", "max_depth");
}

TEST(LoaderDialects, Mitsuba3DifferentiableIntegratorsRenderAsTheirPlainCounterparts) {
  auto prb = loadStrict(sceneWith("<integrator type=\"prb\"/>", "<film type=\"hdrfilm\"/>"));
  EXPECT_NE(prb->integrator().toString().find("PathIntegrator[max_depth=6"), std::string::npos) << prb->integrator().toString();
  auto deeper = loadStrict(sceneWith("<integrator type=\"prb_basic\"><integer name=\"max_depth\" value=\"3\"/></integrator>",
                                     "<film type=\"hdrfilm\"/>"));
  EXPECT_NE(deeper->integrator().toString().find("max_depth=3"), std::string::npos) << deeper->integrator().toString();
  auto vol = loadStrict(sceneWith("<integrator type=\"prbvolpath\"/>", "<film type=\"hdrfilm\"/>"));
  EXPECT_NE(vol->integrator().toString().find("TransientPathIntegrator[max_depth=6"), std::string::npos);
}

TEST(LoaderDialects, BumpAndNormalMapsAreRefusedNamingTheTypeLineAndWhy) {
  for (const char* type : {"bumpmap", "normalmap"}) {
    std::string xml = std::string("<bsdf version=\"3.0.0\" type=\"") + type + "\">\n  <bsdf type=\"diffuse\"/>\n</bsdf>";
    LoadOptions strict;
    strict.strict = true;
    std::string message = loadertest::errorOf([&] { loadObjectFromString(xml, ".", strict, "dialect.xml"); });
    EXPECT_EQ(message.rfind("dialect.xml:1: ", 0), 0u) << message;
    EXPECT_NE(message.find(std::string("plugin \"") + type + "\""), std::string::npos) << message;
    EXPECT_NE(message.find("perturb the shading frame"), std::string::npos) << message;
  }
}

TEST(LoaderDialects, IntegratorsOfOtherRenderersFailNamingTheTypeLineAndWhatToUse) {
  for (const char* type : {"bdpt", "guided_path", "sppm"}) {
    std::string xml = std::string("<scene version=\"3.0.0\">\n  <integrator type=\"") + type + "\"/>\n</scene>";
    std::string message = loadertest::errorOf([&] { loadStrict(xml); });
    EXPECT_EQ(message.rfind("dialect.xml:2: ", 0), 0u) << message;
    EXPECT_NE(message.find(std::string("plugin \"") + type + "\""), std::string::npos) << message;
    EXPECT_NE(message.find("use path (surfaces), transient_path"), std::string::npos) << message;
  }
}

TEST(LoaderDialects, MitransientNlosSensorLoadsAndPhasorFilmFailsNamingWhatToUse) {
  // The capture meter and its integrator are femto's own now (transient_nlos_path).
  auto scene = loadStrict(
      "<scene version=\"3.0.0\">\n<integrator type=\"transient_nlos_path\"/>\n<shape type=\"rectangle\">\n"
      "<sensor type=\"nlos_capture_meter\"><boolean name=\"confocal\" value=\"True\"/>\n"
      "<emitter type=\"projector\"><float name=\"fov\" value=\"0.2\"/></emitter></sensor></shape></scene>");
  EXPECT_NE(scene->sensor().toString().find("NlosCaptureMeter[sensor_origin="), std::string::npos)
      << scene->sensor().toString();
  // Mitsuba 2's spelling is pointed to mitransient's.
  std::string message = loadertest::errorOf([&] {
    loadStrict("<scene version=\"3.0.0\">\n<shape type=\"rectangle\">\n<sensor type=\"nloscapturemeter\"/></shape></scene>");
  });
  EXPECT_EQ(message.rfind("dialect.xml:3: ", 0), 0u) << message;
  EXPECT_NE(message.find("use mitransient's nlos_capture_meter"), std::string::npos) << message;
}
