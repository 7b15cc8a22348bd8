// The boundary loss counted on the scene (boundary_coverage.h): the share
// of a kernel disc that no beam of its direction crosses, at camera points
// beside the boundary of a unit sphere of medium. Head-on at the boundary
// the extensions of entering beams cover what lies outside (the planar
// case, up to the curvature); where the beams graze the sphere (its
// terminator seen from the light) the lines outside miss it and about half
// the disc is lost; deep inside nothing is. And the rule: the radius it
// allows keeps the counted loss within the target.
#include <gtest/gtest.h>

#include <cmath>

#include <transient_beams/boundary_coverage.h>

#include "media_test_util.h"

namespace femto::beams {
namespace {

std::shared_ptr<Scene> sphereOfMedium() {
  return test::loadSceneStrict(R"(<scene version="3.0.0">
    <medium type="homogeneous" id="m"><rgb name="sigma_t" value="1"/><rgb name="albedo" value="0.5"/></medium>
    <shape type="sphere"><float name="radius" value="1"/><ref name="interior" id="m"/></shape>
    <sensor type="perspective"><transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/></film></sensor>
    <emitter type="point"><point name="position" x="0" y="0" z="3"/></emitter></scene>)");
}

const Medium* mediumOf(const Scene& scene) { return scene.shapes()[0]->interiorMedium(); }

TEST(BoundaryCoverage, HeadOnIsCoveredGrazingLosesHalfInsideLosesNothing) {
  auto scene = sphereOfMedium();
  const Medium* m = mediumOf(*scene);
  ASSERT_NE(m, nullptr);
  const double r = 0.05;
  const Vec3f down(0.0f, 0.0f, -1.0f);  // light travelling from +z into the sphere
  // Deep inside: the disc is all medium.
  EXPECT_EQ(uncoveredShare(*scene, Point3f(0.0f, 0.0f, 0.0f), down, Vec3f(0.0f), m, r, 0.0), 0.0);
  // Just below the pole the light enters head-on: the disc reaches out of
  // the sphere by at most r^2 / 2, and those points lie within the
  // extension (r / cos) of the lines entering beside them.
  EXPECT_EQ(uncoveredShare(*scene, Point3f(0.0f, 0.0f, 1.0f - 0.2f * float(r)), down, Vec3f(0.0f), m, r, 0.0), 0.0);
  // On the terminator (x = 1, the light's direction tangent there): the
  // half of the disc beyond x = 1 lies on lines that miss the sphere.
  double grazing = 0.0;
  for (int k = 0; k < 8; ++k)
    grazing += uncoveredShare(*scene, Point3f(1.0f - 1e-4f, 0.0f, 0.0f), down, Vec3f(0.0f), m, r, k / 8.0) / 8.0;
  EXPECT_GT(grazing, 0.35);
  EXPECT_LT(grazing, 0.65);
}

TEST(BoundaryCoverage, TheOneDKernelLosesAlongItsOffsetsOnly) {
  // The 1D kernel gathers beams offset along one direction (w x v): beside
  // the terminator, 0.002 inside, offsets across it (radially) reach out of
  // the beams' shadow cylinder for u > 0.002, (r - 0.002) / 2r = 0.48 of
  // them; offsets along it (tangentially) stay within the cylinder (y^2 <
  // 2 * 0.002 holds for |y| <= r = 0.05 < 0.063).
  auto scene = sphereOfMedium();
  const Medium* m = mediumOf(*scene);
  const double r = 0.05;
  const Vec3f down(0.0f, 0.0f, -1.0f);
  const Point3f x(1.0f - 0.002f, 0.0f, 0.0f);
  double radial = 0.0;
  for (int k = 0; k < 8; ++k) radial += uncoveredShare(*scene, x, down, Vec3f(1.0f, 0.0f, 0.0f), m, r, k / 8.0) / 8.0;
  EXPECT_NEAR(radial, 0.48, 1.0 / DiscPoints);
  for (int k = 0; k < 8; ++k) EXPECT_EQ(uncoveredShare(*scene, x, down, Vec3f(0.0f, 1.0f, 0.0f), m, r, k / 8.0), 0.0);
}

TEST(BoundaryCoverage, RadiusKeepsTheCountedLossWithinTheTarget) {
  auto scene = sphereOfMedium();
  const Medium* m = mediumOf(*scene);
  // Parallel beams along -z through the sphere, an even grid of offsets
  // (entering with extensions, as the photon tracer leaves them), and
  // probes along -x through it at several heights: pairs near the
  // terminator (|x| -> 1 at z = 0) lose, the rest do not.
  std::vector<Beam> beams;
  for (int i = -40; i <= 40; ++i)
    for (int j = -40; j <= 40; ++j) {
      const float x = i / 40.0f, y = j / 40.0f;
      const float rho2 = x * x + y * y;
      if (!(rho2 < 1.0f)) continue;
      const float z = std::sqrt(1.0f - rho2);
      Beam b;
      b.origin = Point3f(x, y, z), b.direction = Vec3f(0.0f, 0.0f, -1.0f), b.length = 2.0f * z;
      b.power = Color3f(1.0f), b.medium = m;
      const Vec3f n(x, y, z);
      b.before = boundaryExtension(n, b.direction), b.after = b.before;
      beams.push_back(b);
    }
  std::vector<ProbeSegment> probes;
  for (int k = -3; k <= 3; ++k) {
    const float z = k / 4.0f, half = std::sqrt(1.0f - z * z);
    ProbeSegment p;
    p.segment.ray = Ray(Point3f(half, 0.0f, z), Vec3f(-1.0f, 0.0f, 0.0f));
    p.segment.tMax = 2.0f * half;
    p.medium = m;
    probes.push_back(p);
  }
  const double upper = 0.2;
  const auto samples = coverageSamples(*scene, nearPairs(beams, probes, upper), upper);
  ASSERT_GT(samples.size(), 100u);
  const double atUpper = boundaryLossShare(*scene, samples, upper);
  EXPECT_GT(atUpper, BoundaryBiasTarget) << "the terminator loses more than the target at r = 0.2";
  // First round: within the target on the samples at `upper`, and not
  // shrunk past the need.
  const double first = radiusWithinTarget(*scene, samples, upper);
  ASSERT_LT(first, upper);
  EXPECT_LE(boundaryLossShare(*scene, samples, first), BoundaryBiasTarget);
  EXPECT_GT(boundaryLossShare(*scene, samples, 1.1 * first), BoundaryBiasTarget) << "not shrunk past the need";
  // Second round: within the target on samples drawn at the first's radius.
  const double r = coveredBoundaryRadius(*scene, beams, probes, upper);
  ASSERT_LE(r, first);
  const auto again = coverageSamples(*scene, nearPairs(beams, probes, first), first);
  EXPECT_LE(boundaryLossShare(*scene, again, r), BoundaryBiasTarget);
}

}  // namespace
}  // namespace femto::beams
