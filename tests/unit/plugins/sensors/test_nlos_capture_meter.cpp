// nlos_capture_meter: where its pixels and laser point lie on the relay wall,
// and the errors of a capture set-up that cannot work, each naming the file
// and line (or the wall) and what to do.
#include <gtest/gtest.h>

#include <femto/core/plugin.h>
#include <femto/render/nlos_sensor.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "loader_test_support.h"
#include "media_test_util.h"

using namespace femto;

namespace {

std::shared_ptr<Scene> loadCapture(const std::string& wall, const std::string& meter, const std::string& extra = "",
                                   const std::string& integrator = "transient_nlos_path") {
  return test::loadSceneStrict(
      str("<scene version=\"3.0.0\">\n<integrator type=\"", integrator, "\"/>\n", wall,
          "\n<sensor type=\"nlos_capture_meter\">\n", meter,
          "<emitter type=\"projector\"><float name=\"fov\" value=\"0.2\"/></emitter>\n"
          "<film type=\"hdrfilm\"><integer name=\"width\" value=\"4\"/><integer name=\"height\" "
          "value=\"2\"/><rfilter type=\"box\"/></film>\n</sensor></shape>\n",
          extra, "</scene>"),
      ".", "nlos.xml");
}

const char* Wall =
    R"(<shape type="rectangle"><transform name="to_world"><scale x="2" y="1"/><translate z="-1"/></transform>)";

}  // namespace

TEST(NlosCaptureMeter, PixelsWatchTheCentresOfTheWallsUvGridFromTheSensor) {
  auto scene = loadCapture(Wall, R"(<point name="sensor_origin" x="0.5" y="0.5" z="3"/>)");
  // Pixel (i, j) of the 4 x 2 film watches uv ((i + 0.5) / 4, (j + 0.5) / 2) of the 4 x 2 wall at z = -1.
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      Ray ray;
      Color3f weight = scene->sensor().sampleRay(Point2f(float(i) + 0.7f, float(j) + 0.2f), Point2f(0.3f), ray);
      EXPECT_EQ(weight, Color3f(1.0f));
      EXPECT_EQ(ray.o, Point3f(0.5f, 0.5f, 3.0f));
      Point3f expected(-2.0f + 4.0f * (float(i) + 0.5f) / 4.0f, -1.0f + 2.0f * (float(j) + 0.5f) / 2.0f, -1.0f);
      Vec3f d = normalize(expected - ray.o);
      EXPECT_NEAR(dot(d, ray.d), 1.0f, 1e-6f) << i << "," << j;
    }
}

TEST(NlosCaptureMeter, LaserTargetIsTheLookatPixelThePointOrEachWatchedPoint) {
  auto pixel = loadCapture(Wall, R"(<point name="laser_lookat_pixel" x="1" y="1.5" z="0"/>)");
  auto& meter = dynamic_cast<const NlosSensor&>(pixel->sensor());
  Point3f t = meter.laserTarget(Point3f(9.0f));
  EXPECT_NEAR(t.x, -2.0f + 4.0f * 0.25f, 1e-5f);
  EXPECT_NEAR(t.y, -1.0f + 2.0f * 0.75f, 1e-5f);
  EXPECT_NEAR(t.z, -1.0f, 1e-5f);
  auto point = loadCapture(Wall, R"(<point name="laser_lookat_3d" x="0.3" y="0.2" z="-1"/>)");
  EXPECT_EQ(dynamic_cast<const NlosSensor&>(point->sensor()).laserTarget(Point3f(9.0f)), Point3f(0.3f, 0.2f, -1.0f));
  auto confocal = loadCapture(Wall, R"(<boolean name="confocal" value="True"/>)");
  EXPECT_EQ(dynamic_cast<const NlosSensor&>(confocal->sensor()).laserTarget(Point3f(0.1f, 0.2f, -1.0f)),
            Point3f(0.1f, 0.2f, -1.0f));
}

TEST(NlosCaptureMeter, BadSetUpsFailNamingTheLineAndWhatToDo) {
  EXPECT_SCENE_ERROR(loadCapture(Wall, "<point name=\"laser_lookat_pixel\" x=\"5\" y=\"1\" z=\"0\"/>\n"), "nlos.xml:5",
                     "(5, 1) is outside the 4x2 film");
  EXPECT_SCENE_ERROR(loadCapture(Wall, "<point name=\"laser_lookat_pixel\" x=\"1\" y=\"1\" z=\"2\"/>\n"), "nlos.xml:5",
                     "its z must be 0");
  EXPECT_SCENE_ERROR(loadCapture(Wall,
                                 "<point name=\"laser_lookat_pixel\" x=\"1\" y=\"1\" z=\"0\"/>"
                                 "<point name=\"laser_lookat_3d\" x=\"1\" y=\"1\" z=\"0\"/>\n"),
                     "nlos.xml:5", "either laser_lookat_pixel or laser_lookat_3d");
  EXPECT_SCENE_ERROR(loadCapture(Wall, "<transform name=\"to_world\"><translate x=\"1\"/></transform>\n"), "nlos.xml:5",
                     "sits at sensor_origin");
  // Only transient_nlos_path traces the nested laser: the others would render black.
  for (const char* other : {"transient_path", "transient_beams", "path"})
    EXPECT_SCENE_ERROR(loadCapture(Wall, "", "", other), "nlos.xml:1",
                       "the capture meter holds its laser, which only transient_nlos_path traces");
  // A second light besides the nested laser, and a wall without a uv square, fail before rendering.
  RenderOptions options;
  options.progress = false;
  auto twoLights = loadCapture(Wall, "", "<emitter type=\"point\"/>\n");
  std::string message = loadertest::errorOf([&] { twoLights->integrator().render(*twoLights, options); });
  EXPECT_NE(message.find("an NLOS scene has exactly one, the laser"), std::string::npos) << message;
  auto sphere = loadCapture("<shape type=\"sphere\">", "");
  message = loadertest::errorOf([&] { sphere->integrator().render(*sphere, options); });
  EXPECT_NE(message.find("the relay wall must be a rectangle or a mesh with texture coordinates"), std::string::npos)
      << message;
}
