// Perspective camera: Mitsuba's conventions (looks along +z, +x is left,
// film (0, 0) is the top-left corner), field-of-view axes and clip planes.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/render/sensor.h>

#include "render_test_util.h"

namespace femto {
namespace {

std::shared_ptr<Sensor> camera(int width, int height, float fov, const std::string& axis, const Transform& toWorld) {
  Properties film("hdrfilm");
  film.setInt("width", width);
  film.setInt("height", height);
  Properties props("perspective");
  props.setFloat("fov", fov);
  props.setString("fov_axis", axis);
  props.setFloat("near_clip", 0.5f);
  props.setTransform("to_world", toWorld);
  props.setObject("film", test::makePlugin<Object>(ObjectKind::Film, film));
  return test::makePlugin<Sensor>(ObjectKind::Sensor, props);
}

void expectDirection(const Vec3f& d, const Vec3f& expected) {
  Vec3f e = normalize(expected);
  EXPECT_NEAR(d.x, e.x, 1e-5f);
  EXPECT_NEAR(d.y, e.y, 1e-5f);
  EXPECT_NEAR(d.z, e.z, 1e-5f);
}

TEST(Perspective, CentreRayFollowsTheViewDirection) {
  Point3f origin(1, 2, 3);
  auto cam = camera(100, 50, 90, "x", Transform::lookAt(origin, {4, 2, 7}, {0, 1, 0}));
  Ray ray;
  EXPECT_EQ(cam->sampleRay({50, 25}, {0.5f, 0.5f}, ray), Color3f(1.0f));
  EXPECT_NEAR(distance(ray.o, origin), 0.0f, 1e-6f);
  expectDirection(ray.d, Vec3f(3, 0, 4));
  EXPECT_NEAR(ray.tmin, 0.5f, 1e-6f);  // near_clip along the optical axis
}

TEST(Perspective, TopLeftPixelLooksUpAndToCameraPlusX) {
  // Looking along -z with +y up, camera +x (= image left) is world -x.
  auto cam = camera(100, 50, 90, "x", Transform::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}));
  Ray ray;
  cam->sampleRay({0, 0}, {0.5f, 0.5f}, ray);
  expectDirection(ray.d, Vec3f(-1, 0.5f, -1));  // tan(45°) = 1 across x, aspect 2 gives 0.5 across y
  cam->sampleRay({100, 50}, {0.5f, 0.5f}, ray);
  expectDirection(ray.d, Vec3f(1, -0.5f, -1));
  // Off-axis ray: the near clip plane is z = near, so tmin grows with 1 / cos.
  cam->sampleRay({0, 0}, {0.5f, 0.5f}, ray);
  EXPECT_NEAR(ray.tmin, 0.5f * length(Vec3f(1, 0.5f, 1)), 1e-5f);
}

TEST(Perspective, FieldOfViewAxes) {
  Transform id;
  Ray ray;
  // fov along y: the top edge centre is at 45°.
  camera(100, 50, 90, "y", id)->sampleRay({50, 0}, {}, ray);
  expectDirection(ray.d, Vec3f(0, 1, 1));
  // "smaller" is y for a landscape film, "larger" x.
  camera(100, 50, 90, "smaller", id)->sampleRay({50, 0}, {}, ray);
  expectDirection(ray.d, Vec3f(0, 1, 1));
  camera(100, 50, 90, "larger", id)->sampleRay({0, 25}, {}, ray);
  expectDirection(ray.d, Vec3f(1, 0, 1));
  // diagonal: the corner is at 45°.
  camera(100, 50, 90, "diagonal", id)->sampleRay({0, 0}, {}, ray);
  EXPECT_NEAR(ray.d.z, std::cos(Pi / 4), 1e-5f);
  EXPECT_THROW(camera(100, 50, 90, "z", id), Error);
  EXPECT_THROW(camera(100, 50, 180, "x", id), Error);
}

TEST(Perspective, FocalLengthIs35mmEquivalentOnTheDiagonal) {
  Properties film("hdrfilm");
  film.setInt("width", 36);
  film.setInt("height", 24);
  Properties props("perspective");
  props.setString("focal_length", "50mm");
  props.setObject("film", test::makePlugin<Object>(ObjectKind::Film, film));
  auto cam = test::makePlugin<Sensor>(ObjectKind::Sensor, props);
  Ray ray;
  cam->sampleRay({36, 0}, {}, ray);  // the film corner sits at (-18, 12) mm, 50 mm away
  expectDirection(ray.d, Vec3f(-18, 12, 50));
}

}  // namespace
}  // namespace femto

namespace femto {
namespace {

TEST(Perspective, ReadsMitsubaCameraAndFilmParameters) {
  // Parameters real Mitsuba scenes give: all must be read (strict mode).
  Properties film("hdrfilm");
  film.setString("file_format", "openexr");
  film.setString("pixel_format", "rgb");
  film.setString("component_format", "float16");
  film.setBool("banner", false);
  film.setBool("high_quality_edges", false);
  auto filmObj = test::makePlugin<Object>(ObjectKind::Film, film);
  EXPECT_TRUE(film.unqueried().empty());
  Properties props("perspective");
  props.setFloat("fov", 40);
  props.setFloat("focus_distance", 1000);
  props.setFloat("shutter_open", 0);
  props.setFloat("shutter_close", 0);
  props.setObject("film", filmObj);
  test::makePlugin<Sensor>(ObjectKind::Sensor, props);
  EXPECT_TRUE(props.unqueried().empty());
}

}  // namespace
}  // namespace femto

namespace femto {
namespace {

std::shared_ptr<Sensor> offsetCamera(float offsetX, float offsetY) {
  Properties film("hdrfilm");
  film.setInt("width", 100);
  film.setInt("height", 50);
  Properties props("perspective");
  props.setFloat("fov", 90);
  props.setFloat("principal_point_offset_x", offsetX);
  props.setFloat("principal_point_offset_y", offsetY);
  props.setObject("film", test::makePlugin<Object>(ObjectKind::Film, film));
  return test::makePlugin<Sensor>(ObjectKind::Sensor, props);
}

// Mitsuba 3 (perspective.cpp, sample_ray) adds the offset, in film-size
// units, to the position sample: pixel (sx, sy) sees what the centred camera
// sees at (sx + offset_x, sy + offset_y). With +x to the image left in camera
// space, a positive offset_x turns the view to the image right (camera -x),
// a positive offset_y down (camera -y).
TEST(Perspective, PrincipalPointOffsetShiftsTheImagePlaneInFilmUnits) {
  auto cam = offsetCamera(0.25f, -0.1f);
  Ray ray;
  // Closed form at z = 1: x = tan(45°) (1 - 2 (px / W + ox)), y = tan(45°) (H / W) (1 - 2 (py / H + oy)).
  cam->sampleRay({50, 25}, {}, ray);
  expectDirection(ray.d, Vec3f(1.0f - 2.0f * 0.75f, 0.5f * (1.0f - 2.0f * 0.4f), 1.0f));
  EXPECT_LT(ray.d.x, 0.0f) << "positive offset_x must look to the image right (camera -x)";
  EXPECT_GT(ray.d.y, 0.0f) << "negative offset_y must look up";
  cam->sampleRay({10, 40}, {}, ray);
  expectDirection(ray.d, Vec3f(1.0f - 2.0f * (0.1f + 0.25f), 0.5f * (1.0f - 2.0f * (0.8f - 0.1f)), 1.0f));
  // The same ray as the centred camera's at the shifted film position; the
  // origin stays at the pinhole (off-axis frustum, no rotation).
  Ray centred;
  offsetCamera(0.0f, 0.0f)->sampleRay({10 + 25, 40 - 5}, {}, centred);
  expectDirection(ray.d, centred.d);
  EXPECT_NEAR(distance(ray.o, Point3f(0.0f)), 0.0f, 1e-6f);
}

TEST(Perspective, FovAxisIsCaseInsensitiveAndSpectralResponseIsRefused) {
  Ray ray;
  camera(100, 50, 90, "Y", Transform())->sampleRay({50, 0}, {}, ray);
  expectDirection(ray.d, Vec3f(0, 1, 1));
  Properties props("perspective");
  props.setFloat("fov", 40);
  props.setFloat("srf", 1.0);
  EXPECT_THROW(test::makePlugin<Sensor>(ObjectKind::Sensor, props), Error);
}

}  // namespace
}  // namespace femto
