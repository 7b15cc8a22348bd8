// The share of a surface photon kernel's disc that lies on the gathering
// point's surface (surface_coverage.h): all of it in the open, half on an
// edge (convex: the floor ends; concave: a wall stands on it), a quarter in
// a corner of three walls, all of it across an index-matched medium
// boundary (not an edge) and on a sphere curving away within reach.
#include <gtest/gtest.h>

#include <transient_beams/surface_coverage.h>

#include "media_test_util.h"

namespace femto::beams {
namespace {

/// The floor [-1, 1]^2 at z = 0 (normal +z), a wall x = 1 (facing -x) and a
/// wall y = 1 (facing -y) standing on it, and an index-matched fog box
/// 0.05 above the floor.
std::shared_ptr<Scene> corner() {
  return test::loadSceneStrict(R"(<scene version="3.0.0">
    <medium type="homogeneous" id="fog"><rgb name="sigma_t" value="0.5"/><rgb name="albedo" value="0.8"/></medium>
    <shape type="rectangle"><bsdf type="diffuse"/></shape>
    <shape type="rectangle"><transform name="to_world"><rotate y="1" angle="-90"/><translate x="1" z="1"/></transform>
      <bsdf type="diffuse"/></shape>
    <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="90"/><translate y="1" z="1"/></transform>
      <bsdf type="diffuse"/></shape>
    <shape type="cube"><transform name="to_world"><scale value="0.5"/><translate x="-0.3" y="-0.3" z="0.55"/></transform>
      <ref name="interior" id="fog"/></shape>
  </scene>)");
}

TEST(SurfaceCoverage, OpenEdgesAndCorners) {
  auto scene = corner();
  const Vec3f up(0.0f, 0.0f, 1.0f);
  const double r = 0.1;
  // In the open floor, under the fog box's boundary (0.05 above: the lifted
  // rays cross it) and far from it.
  EXPECT_EQ(coveredShare(*scene, Point3f(-0.3f, -0.3f, 0.0f), up, r), 1.0);
  EXPECT_EQ(coveredShare(*scene, Point3f(0.0f, -0.5f, 0.0f), up, r), 1.0);
  // On the convex edge x = -1 (the floor ends) and at the foot of the wall
  // x = 1 (concave): half the ring.
  EXPECT_EQ(coveredShare(*scene, Point3f(-1.0f, 0.0f, 0.0f), up, r), 0.5);
  EXPECT_EQ(coveredShare(*scene, Point3f(0.999f, 0.0f, 0.0f), up, r), 0.5);
  // In the corner of the floor and both walls: a quarter.
  EXPECT_EQ(coveredShare(*scene, Point3f(0.999f, 0.999f, 0.0f), up, r), 0.25);
  // On the wall x = 1 (normal -x), at its foot: the floor cuts the lower half.
  EXPECT_EQ(coveredShare(*scene, Point3f(1.0f, 0.0f, 0.001f), Vec3f(-1.0f, 0.0f, 0.0f), r), 0.5);
  // The ring lies at 2r/3: a point 0.08 from the edge keeps it whole at r = 0.1.
  EXPECT_EQ(coveredShare(*scene, Point3f(-0.92f, 0.0f, 0.0f), up, r), 1.0);
  EXPECT_LT(coveredShare(*scene, Point3f(-0.92f, 0.0f, 0.0f), up, 0.2), 1.0);
}

TEST(SurfaceCoverage, ASphereCurvingAwayWithinReachIsCovered) {
  auto scene = test::loadSceneStrict(R"(<scene version="3.0.0">
    <shape type="sphere"><float name="radius" value="1"/><bsdf type="diffuse"/></shape></scene>)");
  // r up to R: the ring (at 2r/3) lies over the sphere, which falls at
  // most 0.26 R below it, within reach.
  for (double r : {0.05, 0.5, 1.0}) EXPECT_EQ(coveredShare(*scene, Point3f(0, 0, 1), Vec3f(0, 0, 1), r), 1.0) << r;
}

}  // namespace
}  // namespace femto::beams
