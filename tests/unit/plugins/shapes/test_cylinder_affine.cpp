// cylinder under affine to_world: a longer axis (x = y != z), an elliptic
// cross-section (x != y) and a shear. Hit points and normals against closed
// forms, the area against Ramanujan's perimeter, and uniform-by-area position
// samples whose pdf matches (the area light's next-event estimate of a
// region's area). Also EllipseArc, the arc-length table behind them.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/ellipse_arc.h>
#include <femto/math/pcg32.h>
#include <femto/render/shape.h>

#include "plugin_util.h"
#include "shape_hit.h"

using namespace femto;
using namespace femto::test;

namespace {

std::shared_ptr<Shape> cylinder(const Transform& toWorld) {
  Properties props("cylinder");
  props.setTransform("to_world", toWorld);
  return createPlugin<Shape>(ObjectKind::Shape, props);
}

void expectNear(const Vec3f& a, const Vec3f& b, float eps) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

constexpr double DoublePi = 3.14159265358979323846;

/// Ramanujan's second approximation of the perimeter of an ellipse with
/// semi-axes a and b (relative error about 3 h^5 / 2^17 with h = ((a-b)/(a+b))^2).
double ramanujanPerimeter(double a, double b) {
  double h = (a - b) * (a - b) / ((a + b) * (a + b));
  return DoublePi * (a + b) * (1.0 + 3.0 * h / (10.0 + std::sqrt(4.0 - 3.0 * h)));
}

/// The exact perimeter (a >= b) by the arithmetic-geometric mean:
/// 2 pi / M(a, b) (a^2 - sum_n 2^(n-1) c_n^2), c_0^2 = a^2 - b^2,
/// c_n = (a_(n-1) - b_(n-1)) / 2 (Abramowitz & Stegun 17.6; converges quadratically).
double agmPerimeter(double a, double b) {
  double an = a, bn = b, sum = 0.5 * (a * a - b * b), weight = 0.5;
  for (int n = 1; n < 12; ++n) {
    double c = 0.5 * (an - bn);
    double next = 0.5 * (an + bn);
    bn = std::sqrt(an * bn);
    an = next;
    weight *= 2.0;
    sum += weight * c * c;
  }
  return 2.0 * DoublePi / an * (a * a - sum);
}

}  // namespace

TEST(CylinderAffine, LongerAxisScalesHeightNotRadius) {
  // <scale x="1.5" y="1.5" z="2"/>: radius 1.5, z from 0 to 2.
  auto cyl = cylinder(Transform::scale({1.5f, 1.5f, 2.0f}));
  EXPECT_NEAR(cyl->surfaceArea(), 2.0f * Pi * 1.5f * 2.0f, 1e-4f);
  SurfaceInteraction si;
  ASSERT_TRUE(hit(*cyl, Ray({5.0f, 0.0f, 1.9f}, {-1, 0, 0}), si));
  expectNear(si.p, {1.5f, 0.0f, 1.9f}, 1e-5f);
  expectNear(si.n, {1, 0, 0}, 1e-5f);
  EXPECT_NEAR(si.uv.y, 0.95f, 1e-5f);
  EXPECT_FALSE(hit(*cyl, Ray({5.0f, 0.0f, 2.1f}, {-1, 0, 0}), si));  // above the top
  // Chord at y = 0.9: x = sqrt(1.5^2 - 0.81) = 1.2, normal (1.2, 0.9) / 1.5.
  ASSERT_TRUE(hit(*cyl, Ray({5.0f, 0.9f, 0.5f}, {-1, 0, 0}), si));
  expectNear(si.p, {1.2f, 0.9f, 0.5f}, 1e-5f);
  expectNear(si.n, {0.8f, 0.6f, 0.0f}, 1e-5f);
}

TEST(CylinderAffine, EllipticCrossSectionHitsAndNormals) {
  // <scale x="1" y="2" z="1"/>, then rotated 90° about z (the long axis becomes
  // world x) and lifted: x^2 / 4 + y^2 = 1 for 1 <= z <= 2.
  auto cyl = cylinder(Transform::translate({0, 0, 1}) * Transform::rotate({0, 0, 1}, 90) * Transform::scale({1, 2, 1}));
  SurfaceInteraction si;
  // Along -y at x = 1.2: y = sqrt(1 - 0.36) = 0.8; the normal is the gradient (x / 4, y).
  ASSERT_TRUE(hit(*cyl, Ray({1.2f, 5.0f, 1.5f}, {0, -1, 0}), si));
  EXPECT_NEAR(si.t, 5.0f - 0.8f, 1e-5f);
  expectNear(si.p, {1.2f, 0.8f, 1.5f}, 1e-5f);
  expectNear(si.n, normalize(Vec3f(0.3f, 0.8f, 0.0f)), 1e-5f);
  // Along -x through the axis: the far end of the long axis, x = 2.
  ASSERT_TRUE(hit(*cyl, Ray({5.0f, 0.0f, 1.2f}, {-1, 0, 0}), si));
  expectNear(si.p, {2.0f, 0.0f, 1.2f}, 1e-5f);
  expectNear(si.n, {1, 0, 0}, 1e-5f);
  // A slanted ray from inside reaches the wall where the closed form says:
  // from the axis along (1, 1, 0) / sqrt 2 the wall is at x = y = 2 / sqrt 5.
  ASSERT_TRUE(hit(*cyl, Ray({0.0f, 0.0f, 1.5f}, normalize(Vec3f(1, 1, 0))), si));
  float w = 2.0f / std::sqrt(5.0f);
  expectNear(si.p, {w, w, 1.5f}, 1e-5f);
  expectNear(si.n, normalize(Vec3f(w / 4.0f, w, 0.0f)), 1e-5f);  // outward, hit from inside
  EXPECT_FALSE(hit(*cyl, Ray({0.0f, 1.01f, 3.0f}, {0, 0, -1}), si));  // outside the ellipse, parallel to the axis
}

TEST(CylinderAffine, ShearedTubeNormalsAreOrthogonalToBothTangents) {
  Matrix4f shear = Matrix4f::fromRows({1, 0.5f, 0.3f, 0, 0, 1, 0, 0, 0, 0.2f, 1.5f, 0, 0, 0, 0, 1});
  auto cyl = cylinder(Transform(shear));
  PCG32 rng(11, 3);
  Transform toWorld(shear);
  for (int i = 0; i < 50; ++i) {
    float phi = 2.0f * Pi * rng.nextFloat(), z = rng.nextFloat();
    Point3f target = toWorld.point({std::cos(phi), std::sin(phi), z});
    SurfaceInteraction si;
    // Aim at the point from outside along the object-space radial direction, mapped to world.
    Vec3f dWorld = normalize(toWorld.vector(Vec3f(std::cos(phi), std::sin(phi), 0.0f)));
    ASSERT_TRUE(hit(*cyl, Ray(target + 3.0f * dWorld, -dWorld), si));
    expectNear(si.p, target, 1e-4f);
    Vec3f tangentPhi = toWorld.vector({-std::sin(phi), std::cos(phi), 0}), tangentZ = toWorld.vector({0, 0, 1});
    EXPECT_NEAR(dot(si.n, normalize(tangentPhi)), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(si.n, normalize(tangentZ)), 0.0f, 1e-5f);
    EXPECT_GT(dot(si.n, dWorld), 0.0f) << "outward";
  }
  // Area: the integral of |(M e_phi) x (M e_z)| over phi (midpoint sum).
  double area = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    double phi = 2.0 * DoublePi * (i + 0.5) / n;
    Vec3d tangentPhi(toWorld.vector({-float(std::sin(phi)), float(std::cos(phi)), 0}));
    area += length(cross(tangentPhi, Vec3d(toWorld.vector({0, 0, 1})))) * 2.0 * DoublePi / n;
  }
  EXPECT_NEAR(cyl->surfaceArea(), area, 1e-5 * area);
}

TEST(CylinderAffine, EllipticAreaIsTheEllipsePerimeterTimesTheHeight) {
  // Semi-axes 1 and 2, height 3: Ramanujan (error ~4e-10 here), the exact
  // AGM perimeter and a 100000-point midpoint sum of the arc length agree.
  auto cyl = cylinder(Transform::scale({1, 2, 3}));
  double midpoint = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    double phi = 2.0 * DoublePi * (i + 0.5) / n;
    midpoint += std::hypot(std::sin(phi), 2.0 * std::cos(phi)) * 2.0 * DoublePi / n;
  }
  EXPECT_NEAR(midpoint, agmPerimeter(2, 1), 1e-9);
  EXPECT_NEAR(ramanujanPerimeter(1, 2), agmPerimeter(2, 1), 1e-8);
  EXPECT_NEAR(cyl->surfaceArea(), 3.0 * ramanujanPerimeter(1, 2), 1e-5 * cyl->surfaceArea());
  // A rotation changes nothing.
  auto turned = cylinder(Transform::rotate(normalize(Vec3f(1, 2, 3)), 40) * Transform::scale({1, 2, 3}));
  EXPECT_NEAR(turned->surfaceArea(), cyl->surfaceArea(), 1e-5 * cyl->surfaceArea());
}

TEST(CylinderAffine, PositionSamplesAreUniformByAreaWithAMatchingPdf) {
  // Elliptic tube with semi-axes 1 (x) and 3 (y). The fraction of samples in
  // the region x > 0.5 must be that region's share of the arc length
  // (computed here by a fine midpoint sum), and the estimate sum(1 / pdf) / n
  // over the region must be its area, as an area light's pdf would give it.
  auto cyl = cylinder(Transform::scale({1, 3, 2}));
  const double twoPi = 2.0 * DoublePi;
  double regionArc = 0.0, totalArc = 0.0;
  const int m = 200000;
  for (int i = 0; i < m; ++i) {
    double phi = twoPi * (i + 0.5) / m, ds = std::hypot(std::sin(phi), 3.0 * std::cos(phi)) * twoPi / m;
    totalArc += ds;
    if (std::cos(phi) > 0.5) regionArc += ds;
  }
  const double regionArea = 2.0 * regionArc, share = regionArc / totalArc;
  PCG32 rng(5, 9);
  const int n = 200000;
  int inRegion = 0;
  double areaEstimate = 0.0;
  for (int i = 0; i < n; ++i) {
    PositionSample ps = cyl->samplePosition({rng.nextFloat(), rng.nextFloat()});
    ASSERT_NEAR(ps.p.x * ps.p.x + ps.p.y * ps.p.y / 9.0f, 1.0f, 1e-4f);
    ASSERT_FLOAT_EQ(ps.pdf, 1.0f / cyl->surfaceArea());
    expectNear(ps.n, normalize(Vec3f(ps.p.x, ps.p.y / 9.0f, 0.0f)), 1e-4f);
    if (ps.p.x > 0.5f) {
      ++inRegion;
      areaEstimate += 1.0 / ps.pdf;
    }
  }
  double sigma = std::sqrt(share * (1.0 - share) / n);
  EXPECT_NEAR(double(inRegion) / n, share, 4.0 * sigma);
  EXPECT_NEAR(areaEstimate / n, regionArea, 4.0 * sigma * cyl->surfaceArea());
  // Uniform phi (the circular tube's sampling) would put only acos(0.5) / pi
  // = 1/3 of the samples there: far outside the tolerance.
  EXPECT_GT(std::abs(share - 1.0 / 3.0), 20.0 * sigma);
}

TEST(EllipseArc, PerimeterAndInversionAgainstQuadrature) {
  const double twoPi = 2.0 * DoublePi;
  for (double ratio : {1.0, 1.5, 4.0, 30.0}) {
    SCOPED_TRACE(ratio);
    EllipseArc arc(Vec3d(1, 0, 0), Vec3d(0, ratio, 0));
    EXPECT_EQ(arc.isCircle(), ratio == 1.0);
    EXPECT_NEAR(arc.perimeter(), agmPerimeter(ratio, 1), 1e-10 * arc.perimeter());
    if (ratio <= 2.0) EXPECT_NEAR(arc.perimeter(), ramanujanPerimeter(1, ratio), 1e-8 * arc.perimeter());
    // angleAtFraction inverts the arc length: check against a midpoint sum.
    for (double fraction : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
      double phi = arc.angleAtFraction(fraction), s = 0.0;
      const int n = 20000;
      for (int i = 0; i < n; ++i) s += arc.speed(phi * (i + 0.5) / n) * phi / n;
      EXPECT_NEAR(s / arc.perimeter(), fraction, 1e-6);
      EXPECT_GE(phi, 0.0);
      EXPECT_LT(phi, twoPi);
    }
  }
  EXPECT_THROW(EllipseArc(Vec3d(1, 0, 0), Vec3d(2, 0, 0)), Error);
}
