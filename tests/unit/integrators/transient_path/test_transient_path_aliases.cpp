// mitransient's and Mitsuba 2's names for transient_path render what
// transient_path renders with the same parameters, bit for bit; mitransient's
// discard_direct_light drops exactly the emission that phase/BSDF sampling
// (and the camera ray) finds; moment refuses a transient film.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include <femto/image/image_io.h>
#include <femto/render/integrator.h>
#include <femto/loop/render_loop.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "plugin_util.h"
#include "render_test_util.h"

namespace femto {
namespace {

/// A fog cube lit from above, seen by a 12x12 transient film (mitransient's
/// names); `integrator` is the whole <integrator> element.
std::string fogScene(const std::string& integrator, const std::string& extraShapes = "") {
  return R"(<scene version="3.0.0">)" + integrator + R"(
  <sensor type="perspective">
    <float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <sampler type="independent"><integer name="sample_count" value="6"/></sampler>
    <film type="transient_hdr_film">
      <integer name="width" value="12"/><integer name="height" value="12"/>
      <integer name="temporal_bins" value="30"/><float name="bin_width_opl" value="0.15"/>
      <float name="start_opl" value="2.5"/><rfilter type="box"/>
    </film>
  </sensor>
  <medium type="homogeneous" id="fog">
    <rgb name="sigma_t" value="1.2"/><rgb name="albedo" value="0.85"/>
    <phase type="hg"><float name="g" value="0.4"/></phase>
  </medium>
  <shape type="cube"><ref name="interior" id="fog"/></shape>
  <emitter type="point"><point name="position" x="0" y="1.6" z="0.3"/><rgb name="intensity" value="6"/></emitter>
  <shape type="rectangle">
    <transform name="to_world"><scale value="3"/><translate z="-1.5"/></transform>
    <bsdf type="diffuse"/>
  </shape>)" + extraShapes + "\n</scene>";
}

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Renders `xml` to dir/stem.exr (+ .npy) with a fixed seed.
void render(const std::string& xml, const std::filesystem::path& out) {
  LoadOptions load;
  load.strict = true;
  auto scene = loadSceneFromString(xml, ".", load, "alias.xml");
  RenderOptions options;
  options.output = out;
  options.progress = false;
  options.seed = 7;
  ASSERT_TRUE(scene->integrator().render(*scene, options).completed);
}

const std::string Parameters = R"(<integer name="max_depth" value="5"/><integer name="rr_depth" value="3"/>
  <boolean name="camera_unwarp" value="False"/><string name="temporal_filter" value="gaussian"/>
  <float name="gaussian_stddev" value="1.5"/>)";

}  // namespace

TEST(TransientPathAliases, PrbVolpathAndTransientpathEqualTransientPathBitwise) {
  auto dir = test::scratchDir("transient-path-aliases");
  render(fogScene("<integrator type=\"transient_path\">" + Parameters + "</integrator>"), dir / "path.exr");
  render(fogScene("<integrator type=\"transient_prbvolpath\">" + Parameters + "</integrator>"), dir / "prb.exr");
  render(fogScene("<integrator type=\"transientpath\">" + Parameters + "</integrator>"), dir / "old.exr");
  std::string reference = fileBytes(dir / "path.npy");
  ASSERT_GT(reference.size(), 12u * 12u * 30u * 3u * 4u);
  EXPECT_TRUE(reference == fileBytes(dir / "prb.npy")) << "transient_prbvolpath's volume differs from transient_path's";
  EXPECT_TRUE(reference == fileBytes(dir / "old.npy")) << "transientpath's volume differs from transient_path's";
  EXPECT_TRUE(fileBytes(dir / "path.exr") == fileBytes(dir / "prb.exr"));
  // Not trivially equal: another depth gives another volume.
  render(fogScene("<integrator type=\"transient_prbvolpath\"><integer name=\"max_depth\" value=\"2\"/>"
                  "<string name=\"temporal_filter\" value=\"gaussian\"/><float name=\"gaussian_stddev\" value=\"1.5\"/>"
                  "<integer name=\"rr_depth\" value=\"3\"/></integrator>"),
         dir / "shallow.exr");
  EXPECT_FALSE(reference == fileBytes(dir / "shallow.npy"));
  std::filesystem::remove_all(dir);
}

TEST(TransientPathAliases, DiscardDirectLightDropsOnlyEmissionFoundByScattering) {
  auto dir = test::scratchDir("discard-direct-light");
  const std::string depth = "<integer name=\"max_depth\" value=\"4\"/>";
  // A point light is found by next-event estimation only: nothing to drop.
  render(fogScene("<integrator type=\"transient_path\">" + depth + "</integrator>"), dir / "keep.exr");
  render(fogScene("<integrator type=\"transient_path\">" + depth +
                  "<boolean name=\"discard_direct_light\" value=\"true\"/></integrator>"),
         dir / "drop.exr");
  EXPECT_TRUE(fileBytes(dir / "keep.npy") == fileBytes(dir / "drop.npy"));
  // An area light in view: its pixels go black (the camera ray finds it),
  // the light it casts stays (next-event estimation).
  const std::string lamp = R"(<shape type="rectangle">
    <transform name="to_world"><scale value="0.4"/><translate x="0.9" y="0.9" z="1.3"/></transform>
    <emitter type="area"><rgb name="radiance" value="40"/></emitter></shape>)";
  render(fogScene("<integrator type=\"transient_path\">" + depth + "</integrator>", lamp), dir / "lamp.exr");
  render(fogScene("<integrator type=\"transient_path\">" + depth +
                  "<boolean name=\"discard_direct_light\" value=\"true\"/></integrator>", lamp),
         dir / "lamp_drop.exr");
  Bitmap with = readImage(dir / "lamp.exr"), without = readImage(dir / "lamp_drop.exr");
  int brightPixels = 0;
  double restWith = 0.0, restWithout = 0.0;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x) {
      float a = with.pixel(x, y)[1], b = without.pixel(x, y)[1];
      if (a > 20.0f) {
        ++brightPixels;
        EXPECT_LT(b, 0.1f * a) << "pixel " << x << "," << y << " still sees the lamp";
      } else {
        restWith += a, restWithout += b;
      }
    }
  EXPECT_GT(brightPixels, 0) << "the lamp is not in view";
  EXPECT_GT(restWithout, 0.3 * restWith) << "the lamp's light on the fog and the wall was dropped too";
  std::filesystem::remove_all(dir);
}

TEST(TransientPathAliases, MomentRefusesATransientFilmBeforeRendering) {
  LoadOptions load;
  auto scene = loadSceneFromString(
      fogScene("<integrator type=\"moment\">\n<integrator type=\"transient_path\"/></integrator>"), ".", load, "moment.xml");
  RenderOptions options;
  options.output = test::scratchDir("moment-transient") / "out.exr";
  options.progress = false;
  std::string message = test::errorMessageOf([&] { scene->integrator().render(*scene, options); });
  EXPECT_EQ(message.rfind("moment.xml:1: ", 0), 0u) << message;
  EXPECT_NE(message.find("cannot fill the time-resolved film"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(options.output.parent_path() / "out.npy"));
}

}  // namespace femto
