// CameraReach (camera_reach.h): light at x with OPL tau reaches a camera ray's
// origin no earlier than tau + its distance to the origins' ball, so photons
// and beams past the film's window + the kernels' reach can end. The ball
// holds every origin; the cut length is the first point past the limit.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/render/scene.h>
#include <femto/render/sensor.h>
#include <transient_beams/camera_reach.h>

#include "media_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

std::string cameraScene(const std::string& sensor) {
  return str(R"(<scene version="3.0.0"><integrator type="transient_path"/>
  <sensor type=")", sensor, R"("><float name="fov" value="40"/>)",
             sensor == "thinlens" ? R"(<float name="aperture_radius" value="0.2"/><float name="focus_distance" value="3"/>)"
                                  : "",
             R"(<transform name="to_world"><lookat origin="1, 2, 3" target="0, 0, 0" up="0, 1, 0"/></transform>
    <film type="transient"><integer name="width" value="8"/><integer name="height" value="6"/>
      <integer name="temporal_bins" value="4"/><float name="start_opl" value="0"/><float name="bin_width_opl" value="1"/>
      <rfilter type="box"/></film></sensor>
  <shape type="sphere"><float name="radius" value="0.5"/></shape></scene>)");
}

}  // namespace

TEST(CameraReach, TheBallHoldsEveryRayOrigin) {
  for (const char* type : {"perspective", "thinlens"}) {
    auto scene = loadSceneStrict(cameraScene(type));
    const beams::CameraReach reach = beams::cameraReach(*scene, true);
    ASSERT_TRUE(reach.valid) << type;
    if (std::string(type) == "perspective") EXPECT_LT(reach.radius, 1e-4f);
    if (std::string(type) == "thinlens") EXPECT_NEAR(reach.radius, 0.2f, 0.01f);
    PCG32 rng(7, 3);
    for (int i = 0; i < 2000; ++i) {
      Ray ray;
      scene->sensor().sampleRay(Point2f(8 * rng.nextFloat(), 6 * rng.nextFloat()),
                                Point2f(rng.nextFloat(), rng.nextFloat()), ray);
      EXPECT_LE(distance(ray.o, reach.center), reach.radius * 1.0001f + 1e-5f) << type;
      EXPECT_EQ(reach.distance(ray.o), 0.0f);
    }
    EXPECT_FALSE(beams::cameraReach(*scene, false).valid) << "without observer time the camera segment adds nothing";
  }
}

TEST(CameraReach, ReachableLengthEndsWhereTheLimitIsPassed) {
  beams::CameraReach reach;
  reach.center = Point3f(0.0f), reach.radius = 0.0f, reach.valid = true;
  // A beam from (0, 0, 1) away from the camera: opl + eta s + (1 + s) = limit at s = (limit - opl - 1) / (eta + 1).
  const Point3f o(0.0f, 0.0f, 1.0f);
  const Vec3f d(0.0f, 0.0f, 1.0f);
  const float s = beams::reachableLength(reach, o, d, 10.0f, 0.5, 1.33f, 5.0);
  EXPECT_NEAR(s, (5.0 - 0.5 - 1.0) / 2.33, 1e-5);
  EXPECT_EQ(beams::reachableLength(reach, o, d, 1.0f, 0.5, 1.33f, 5.0), 1.0f) << "the whole beam is in reach";
  EXPECT_EQ(beams::reachableLength(reach, o, d, 1.0f, 4.5, 1.33f, 5.0), 0.0f) << "none of it";
  // Toward the camera (eta = 1): the sum stays constant, never cut before the limit.
  EXPECT_EQ(beams::reachableLength(reach, Point3f(0, 0, 3), -d, 2.0f, 1.0, 1.0f, 4.5), 2.0f);
  beams::CameraReach none;
  EXPECT_EQ(beams::reachableLength(none, o, d, 10.0f, 4.9, 1.33f, 5.0), 10.0f) << "no bound: uncut";
}
