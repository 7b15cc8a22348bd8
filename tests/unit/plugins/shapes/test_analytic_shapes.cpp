// disk and cylinder: exact intersections (closed forms), areas, uniform
// position sampling on the surface, and the Embree user-geometry path.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <femto/math/pcg32.h>
#include <femto/render/scene.h>
#include <femto/xml/loader.h>

#include "plugin_util.h"
#include "shape_hit.h"

using namespace femto;
using namespace femto::test;

namespace {

std::shared_ptr<Shape> makeShape(const std::string& type, Properties props = {}) {
  props.setPluginName(type);
  return createPlugin<Shape>(ObjectKind::Shape, props);
}

void expectNear(const Vec3f& a, const Vec3f& b, float eps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

}  // namespace

TEST(DiskShape, UnitDiskFacingPlusZ) {
  auto disk = makeShape("disk");
  EXPECT_NEAR(disk->surfaceArea(), Pi, 1e-6f);
  SurfaceInteraction si;
  ASSERT_TRUE(hit(*disk, Ray({0.6f, 0.0f, 2.0f}, {0, 0, -1}), si));
  EXPECT_NEAR(si.t, 2.0f, 1e-6f);
  expectNear(si.p, {0.6f, 0.0f, 0.0f}, 1e-6f);
  expectNear(si.n, {0, 0, 1}, 1e-6f);
  EXPECT_NEAR(si.uv.x, 0.6f, 1e-6f);  // uv = (r, phi / 2pi)
  EXPECT_NEAR(si.uv.y, 0.0f, 1e-6f);
  EXPECT_FALSE(hit(*disk, Ray({0.8f, 0.8f, 2.0f}, {0, 0, -1}), si));  // r = 1.13 > 1
  EXPECT_FALSE(hit(*disk, Ray({0.0f, 0.0f, 2.0f}, {1, 0, 0}), si));   // parallel
  EXPECT_FALSE(hit(*disk, Ray({0.0f, 0.0f, 2.0f}, {0, 0, -1}, 0.0f, 1.5f), si));  // beyond tmax
  // A grazing ray from below at an angle: t = |z| / cos.
  Vec3f d = normalize(Vec3f(1, 0, 1));
  ASSERT_TRUE(hit(*disk, Ray({-0.5f, 0.0f, -0.5f}, d), si));
  EXPECT_NEAR(si.t, 0.5f * std::sqrt(2.0f), 1e-6f);
  expectNear(si.p, {0, 0, 0}, 1e-6f);
}

TEST(DiskShape, AffineToWorldMakesAnEllipseWithExactArea) {
  Properties props;
  props.setTransform("to_world", Transform::translate({0, 0, 1}) * Transform::rotate({0, 1, 0}, 90) *
                                     Transform::scale({2, 3, 1}));
  props.setBool("flip_normals", true);
  auto disk = makeShape("disk", props);
  EXPECT_NEAR(disk->surfaceArea(), 6.0f * Pi, 1e-4f);  // ellipse with semi-axes 2 and 3
  // rotate +90 about y maps +z to +x; flipped, the normal is -x.
  SurfaceInteraction si;
  ASSERT_TRUE(hit(*disk, Ray({5.0f, 2.5f, 1.0f}, {-1, 0, 0}), si));  // y = 2.5 < 3: inside
  EXPECT_NEAR(si.t, 5.0f, 1e-5f);
  expectNear(si.p, {0.0f, 2.5f, 1.0f}, 1e-5f);
  expectNear(si.n, {-1, 0, 0}, 1e-6f);
  EXPECT_FALSE(hit(*disk, Ray({5.0f, 0.0f, 1.0f + 2.1f}, {-1, 0, 0}), si));  // z offset 2.1 > 2
  // Sampled points lie on the ellipse, with pdf 1 / area.
  PCG32 rng(7, 1);
  for (int i = 0; i < 100; ++i) {
    PositionSample ps = disk->samplePosition({rng.nextFloat(), rng.nextFloat()});
    EXPECT_NEAR(ps.p.x, 0.0f, 1e-5f);
    float e = (ps.p.z - 1.0f) * (ps.p.z - 1.0f) / 4.0f + ps.p.y * ps.p.y / 9.0f;
    EXPECT_LE(e, 1.0f + 1e-5f);
    EXPECT_FLOAT_EQ(ps.pdf, 1.0f / disk->surfaceArea());
  }
}

TEST(CylinderShape, OpenTubeHitsMatchTheClosedForm) {
  Properties props;
  props.setPoint("p0", {1, 0, 0});
  props.setPoint("p1", {1, 0, 4});
  props.setFloat("radius", 0.5);
  auto cyl = makeShape("cylinder", props);
  EXPECT_NEAR(cyl->surfaceArea(), 2.0f * Pi * 0.5f * 4.0f, 1e-5f);
  SurfaceInteraction si;
  // From outside along -x at height 1: hits the near side x = 1.5.
  ASSERT_TRUE(hit(*cyl, Ray({5.0f, 0.0f, 1.0f}, {-1, 0, 0}), si));
  EXPECT_NEAR(si.t, 3.5f, 1e-5f);
  expectNear(si.p, {1.5f, 0.0f, 1.0f}, 1e-5f);
  expectNear(si.n, {1, 0, 0}, 1e-5f);
  EXPECT_NEAR(si.uv.y, 0.25f, 1e-5f);  // height fraction
  // Off-centre chord: y = 0.3 gives x = 1 + sqrt(0.25 - 0.09) = 1.4.
  ASSERT_TRUE(hit(*cyl, Ray({5.0f, 0.3f, 2.0f}, {-1, 0, 0}), si));
  expectNear(si.p, {1.4f, 0.3f, 2.0f}, 1e-5f);
  expectNear(si.n, {0.8f, 0.6f, 0.0f}, 1e-5f);
  // Open ends: a ray down the axis misses; one entering through the open
  // top hits the inside wall where its slope takes it.
  EXPECT_FALSE(hit(*cyl, Ray({1.0f, 0.0f, 10.0f}, {0, 0, -1}), si));
  Vec3f d = normalize(Vec3f(1, 0, -1));
  ASSERT_TRUE(hit(*cyl, Ray({1.0f, 0.0f, 4.2f}, d), si));  // reaches x = 1.5 at z = 3.7
  expectNear(si.p, {1.5f, 0.0f, 3.7f}, 1e-5f);
  expectNear(si.n, {1, 0, 0}, 1e-5f);  // outward normal although hit from inside
  // Above the top the near root is skipped and the far side too: a miss.
  EXPECT_FALSE(hit(*cyl, Ray({5.0f, 0.0f, 4.1f}, {-1, 0, 0}), si));
}

TEST(CylinderShape, SamplesLieOnTheTube) {
  Properties props;
  props.setTransform("to_world", Transform::translate({0, 2, 0}) * Transform::scale({2, 2, 2}));
  props.setBool("flip_normals", true);
  auto cyl = makeShape("cylinder", props);
  EXPECT_NEAR(cyl->surfaceArea(), 2.0f * Pi * 2.0f * 2.0f, 1e-4f);
  PCG32 rng(3, 1);
  for (int i = 0; i < 100; ++i) {
    PositionSample ps = cyl->samplePosition({rng.nextFloat(), rng.nextFloat()});
    Vec3f radial(ps.p.x, ps.p.y - 2.0f, 0.0f);
    EXPECT_NEAR(length(radial), 2.0f, 1e-4f);
    EXPECT_GE(ps.p.z, -1e-5f);
    EXPECT_LE(ps.p.z, 2.0f + 1e-5f);
    expectNear(ps.n, -radial / length(radial), 1e-4f);  // flipped: toward the axis
  }
}

TEST(AnalyticShapes, DiskAndCylinderThroughTheSceneAccel) {
  LoadOptions options;
  options.strict = true;
  auto scene = loadSceneFromString(R"(<scene version="3.0.0">
    <shape type="disk"><transform name="to_world"><translate z="-1"/></transform></shape>
    <shape type="cylinder"><float name="radius" value="0.25"/></shape>
  </scene>)", std::filesystem::temp_directory_path(), options, "analytic.xml");
  SurfaceInteraction si;
  ASSERT_TRUE(scene->rayIntersect(Ray({0.5f, 0.0f, 3.0f}, {0, 0, -1}), si));  // beside the tube: the disk
  EXPECT_NEAR(si.t, 4.0f, 1e-5f);
  expectNear(si.wi, {0, 0, 1}, 1e-6f);
  ASSERT_TRUE(scene->rayIntersect(Ray({3.0f, 0.0f, 0.5f}, {-1, 0, 0}), si));  // the tube's side
  EXPECT_NEAR(si.t, 2.75f, 1e-5f);
  EXPECT_TRUE(scene->rayTest(Ray({3.0f, 0.0f, 0.5f}, {-1, 0, 0}, 0.0f, 3.0f)));
  EXPECT_FALSE(scene->rayTest(Ray({3.0f, 0.0f, 0.5f}, {-1, 0, 0}, 0.0f, 2.5f)));
}
