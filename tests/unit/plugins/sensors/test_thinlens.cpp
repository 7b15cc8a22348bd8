// Thin-lens camera (Mitsuba's thinlens): rays leave the aperture disk and
// meet on the focal plane where the pinhole ray through the same film
// position does; a zero aperture is the perspective camera; clip planes stay
// planes of camera space.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/render/sensor.h>
#include <femto/xml/loader.h>

#include "loader_test_support.h"
#include "render_test_util.h"

namespace femto {
namespace {

const Transform ToWorld = Transform::translate(Vec3f(1.0f, 2.0f, 3.0f)) * Transform::rotate(Vec3f(0, 1, 0), 30.0f);

std::shared_ptr<Sensor> camera(const std::string& type, float aperture, float focus) {
  Properties film("hdrfilm");
  film.setInt("width", 40);
  film.setInt("height", 30);
  Properties props(type);
  props.setFloat("fov", 50.0f);
  props.setFloat("near_clip", 0.5f);
  props.setTransform("to_world", ToWorld);
  if (type == "thinlens") {
    props.setFloat("aperture_radius", aperture);
    props.setFloat("focus_distance", focus);
  }
  props.setObject("film", test::makePlugin<Object>(ObjectKind::Film, film));
  return test::makePlugin<Sensor>(ObjectKind::Sensor, props);
}

/// The point at camera-space depth z along `ray`.
Point3f atCameraDepth(const Ray& ray, float z) {
  Transform toCamera = ToWorld.inverse();
  Point3f o = toCamera.point(ray.o);
  Vec3f d = toCamera.vector(ray.d);
  return ToWorld.point(o + d * ((z - o.z) / d.z));
}

}  // namespace

TEST(ThinLens, RaysThroughOneFilmPositionMeetOnTheFocalPlane) {
  const float focus = 4.0f, aperture = 0.3f;
  auto lens = camera("thinlens", aperture, focus);
  auto pinhole = camera("perspective", 0.0f, 0.0f);
  PCG32 rng(3, 1);
  for (Point2f filmPos : {Point2f(20.0f, 15.0f), Point2f(3.5f, 27.0f), Point2f(39.0f, 0.5f)}) {
    Ray reference;
    pinhole->sampleRay(filmPos, Point2f(0.5f, 0.5f), reference);
    Point3f expected = atCameraDepth(reference, focus);
    double meanSquaredRadius = 0.0;
    const int n = 4000;
    for (int i = 0; i < n; ++i) {
      Ray ray;
      EXPECT_EQ(lens->sampleRay(filmPos, Point2f(rng.nextFloat(), rng.nextFloat()), ray), Color3f(1.0f));
      Point3f onFocalPlane = atCameraDepth(ray, focus);
      EXPECT_NEAR(distance(onFocalPlane, expected), 0.0f, 1e-4f);
      Point3f lensPoint = ToWorld.inverse().point(ray.o);
      EXPECT_NEAR(lensPoint.z, 0.0f, 1e-5f);
      float r2 = lensPoint.x * lensPoint.x + lensPoint.y * lensPoint.y;
      EXPECT_LE(r2, aperture * aperture * (1.0f + 1e-4f));
      meanSquaredRadius += r2 / n;
    }
    // Uniform by area over the disk: E[r^2] = R^2 / 2, standard error R^2 / sqrt(12 n).
    EXPECT_NEAR(meanSquaredRadius, 0.5 * aperture * aperture, 5.0 * aperture * aperture / std::sqrt(12.0 * n));
  }
}

TEST(ThinLens, ZeroApertureIsThePerspectiveCameraAndClipPlanesStayPlanes) {
  auto lens = camera("thinlens", 0.0f, 2.0f);
  auto pinhole = camera("perspective", 0.0f, 0.0f);
  for (Point2f filmPos : {Point2f(20.0f, 15.0f), Point2f(0.0f, 0.0f), Point2f(33.3f, 21.7f)}) {
    Ray a, b;
    lens->sampleRay(filmPos, Point2f(0.3f, 0.8f), a);
    pinhole->sampleRay(filmPos, Point2f(0.3f, 0.8f), b);
    EXPECT_NEAR(distance(a.o, b.o), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(a.d, b.d), 1.0f, 1e-6f);
    EXPECT_NEAR(a.tmin, b.tmin, 1e-5f * b.tmin);
  }
  // With an aperture, the near clip is still the plane z = near_clip of camera space.
  auto wide = camera("thinlens", 0.5f, 3.0f);
  Ray ray;
  wide->sampleRay(Point2f(5.0f, 25.0f), Point2f(0.9f, 0.1f), ray);
  Point3f nearPoint = ToWorld.inverse().point(ray(ray.tmin));
  EXPECT_NEAR(nearPoint.z, 0.5f, 1e-4f);
}

TEST(ThinLens, ApertureIsRequiredAndCheckedAtItsLine) {
  auto load = [](const std::string& body) {
    return loadObjectFromString("<sensor type=\"thinlens\">\n" + body + "</sensor>", ".", {}, "lens.xml");
  };
  EXPECT_SCENE_ERROR(load(""), "lens.xml:1", "missing the required parameter \"aperture_radius\"");
  EXPECT_SCENE_ERROR(load("<float name=\"aperture_radius\" value=\"-1\"/>"), "lens.xml:2", "at least 0");
  EXPECT_SCENE_ERROR(load("<float name=\"aperture_radius\" value=\"0.1\"/>\n<float name=\"focus_distance\" value=\"0\"/>"),
                     "lens.xml:3", "must be positive");
}

}  // namespace femto
