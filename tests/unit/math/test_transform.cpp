#include <gtest/gtest.h>

#include <femto/base/error.h>
#include <femto/math/transform.h>

using namespace femto;

namespace {
void expectNear(const Vec3f& a, const Vec3f& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}
}  // namespace

TEST(Transform, ComposesRightToLeft) {
  Transform t = Transform::translate({1, 2, 3}) * Transform::scale({2, 2, 2});
  expectNear(t.point({1, 1, 1}), {3, 4, 5});
  expectNear(t.vector({1, 1, 1}), {2, 2, 2});
}

TEST(Transform, InverseRoundTrips) {
  Transform t = Transform::rotate({0.3f, 1, 0.2f}, 37.0f) * Transform::translate({1, -2, 0.5f}) *
                Transform::scale({1, 3, 0.5f});
  Point3f p(0.7f, -1.2f, 2.5f);
  expectNear(t.inverse().point(t.point(p)), p);
  Matrix4f inv;
  ASSERT_TRUE(t.matrix().inverse(inv));
  Matrix4f id = t.matrix() * inv;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(id.m[i][j], i == j ? 1.0f : 0.0f, 1e-5f);
}

TEST(Transform, RotateIsRightHanded) {
  expectNear(Transform::rotate({0, 0, 1}, 90).vector({1, 0, 0}), {0, 1, 0});
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
  Transform t = Transform::scale({4, 1, 1});
  Vec3f tangent = t.vector(normalize(Vec3f(1, -1, 0)));
  Vec3f n = t.normal(normalize(Vec3f(1, 1, 0)));
  EXPECT_NEAR(dot(tangent, n), 0.0f, 1e-6f);
}

TEST(Transform, LookAtMapsForwardToTarget) {
  Transform t = Transform::lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
  expectNear(t.vector({0, 0, 1}), {0, 0, -1});
  expectNear(t.vector({0, 1, 0}), {0, 1, 0});
  expectNear(t.point({0, 0, 0}), {0, 0, 5});
}

TEST(Transform, SingularMatrixIsAnError) {
  Matrix4f m{};
  EXPECT_THROW(Transform{m}, Error);
  EXPECT_THROW(Transform::scale({0, 1, 1}), Error);
}
