// Time-gated distance ranges (transport/time_gate.h) against bisection on
// the path length g(t) = t + |o + t d - c|, and equiangular sampling of a
// part [tStart, tEnd] of a segment: its density integrates to one there and
// its samples stay in it. Residual-time truncation: the reach against
// bisection on eta t + |o + t d - c| (eta >= 1); the free flights
// conditioned to scatter before it are the media's (test_media_homogeneous.cpp,
// test_media_heterogeneous.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/math/warp.h>
#include <femto/transport/equiangular.h>
#include <femto/transport/time_gate.h>

#include "media_test_util.h"

using namespace femto;
using namespace femto::test;

namespace {

double pathLength(const Point3f& o, const Vec3f& d, const Point3f& c, double t, double eta = 1.0) {
  return eta * t + double(distance(o + d * float(t), c));
}

/// The t with pathLength = length, by bisection (g is non-decreasing).
double bisect(const Point3f& o, const Vec3f& d, const Point3f& c, double length, double eta = 1.0) {
  double lo = 0.0, hi = 1.0;
  while (pathLength(o, d, c, hi, eta) < length) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    (pathLength(o, d, c, mid, eta) < length ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST(TimeGate, DistanceRangeMatchesBisectionOnThePathLength) {
  PCG32 rng(7, 1);
  for (int i = 0; i < 200; ++i) {
    Point3f o(rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1);
    Point3f c(rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1);
    Vec3f d = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()});
    double r = distance(o, c);
    double lengthA = r * (0.5 + 2.0 * rng.nextFloat()), lengthB = lengthA + 3.0 * rng.nextFloat();
    DistanceRange range = distancesArrivingWithin(o, d, c, lengthA, lengthB);
    double expectedA = lengthA <= r ? 0.0 : bisect(o, d, c, lengthA), expectedB = bisect(o, d, c, lengthB);
    EXPECT_NEAR(range.t0, expectedA, 1e-4 * (1.0 + expectedA)) << "case " << i << " lengthA " << lengthA << " r " << r;
    EXPECT_NEAR(range.t1, expectedB, 1e-4 * (1.0 + expectedB)) << "case " << i << " lengthB " << lengthB << " r " << r;
  }
}

TEST(TimeGate, OpenWindowsAndALightAheadOnTheRay) {
  const Point3f o(0.0f), c(0.0f, 0.0f, 2.0f);
  const Vec3f d(0.0f, 0.0f, 1.0f);
  // Before the light g(t) = 2; past it g(t) = 2t - 2.
  DistanceRange range = distancesArrivingWithin(o, d, c, 3.0, 4.0);
  EXPECT_NEAR(range.t0, 2.5, 1e-6);
  EXPECT_NEAR(range.t1, 3.0, 1e-6);
  DistanceRange all = distancesArrivingWithin(o, Vec3f(1.0f, 0.0f, 0.0f), c, -Infinity, Infinity);
  EXPECT_EQ(all.t0, 0.0);
  EXPECT_EQ(all.t1, double(Infinity));
  EXPECT_TRUE(distancesArrivingWithin(o, d, c, 0.5, 1.5).empty()) << "a window before the light's distance";
}

TEST(TimeGate, EquiangularOverAPartOfTheSegmentIsNormalisedAndStaysInIt) {
  const Point3f o(0.0f), c(0.3f, 0.2f, 1.0f);
  const Vec3f d(0.0f, 0.0f, 1.0f);
  for (auto [tStart, tEnd] : {std::pair{0.4f, 1.7f}, std::pair{1.2f, 5.0f}}) {
    EquiangularSegment seg = equiangularSegment(o, d, tStart, tEnd, c);
    ASSERT_TRUE(seg.valid());
    const int steps = 20000;  // Simpson, even
    double h = double(tEnd - tStart) / steps, integral = pdfEquiangular(seg, tStart) + pdfEquiangular(seg, tEnd);
    for (int k = 1; k < steps; ++k) integral += (k % 2 ? 4.0 : 2.0) * pdfEquiangular(seg, float(tStart + k * h));
    EXPECT_NEAR(integral * h / 3.0, 1.0, 1e-4);
    EXPECT_EQ(pdfEquiangular(seg, tStart * 0.99f), 0.0f);
    EXPECT_EQ(pdfEquiangular(seg, tEnd * 1.01f), 0.0f);
    PCG32 rng(3, 1);
    for (int i = 0; i < 1000; ++i) {
      float pdf = 0.0f, t = sampleEquiangular(seg, rng.nextFloat(), pdf);
      ASSERT_GE(t, tStart);
      ASSERT_LE(t, tEnd);
      ASSERT_NEAR(pdf, pdfEquiangular(seg, t), 1e-5f * pdf);
    }
  }
}

TEST(TimeGate, ReachMatchesBisectionForAnyRefractiveIndex) {
  PCG32 rng(11, 1);
  for (int i = 0; i < 300; ++i) {
    Point3f o(rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1);
    Point3f c(rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1, rng.nextFloat() * 2 - 1);
    Vec3f d = warp::squareToUniformSphere({rng.nextFloat(), rng.nextFloat()});
    double eta = i % 3 == 0 ? 1.0 : 1.0 + rng.nextFloat(), r = distance(o, c);
    double length = r * (0.5 + 3.0 * rng.nextFloat());
    double expected = length <= r ? 0.0 : bisect(o, d, c, length, eta);
    EXPECT_NEAR(distanceReaching(o, d, c, eta, length), expected, 1e-4 * (1.0 + expected))
        << "case " << i << " eta " << eta << " length " << length << " r " << r;
    if (eta == 1.0)
      EXPECT_NEAR(distanceReaching(o, d, c, eta, length), distancesArrivingWithin(o, d, c, 0.0, length).t1,
                  1e-9 * (1.0 + expected));
  }
  EXPECT_EQ(distanceReaching(Point3f(0.0f), Vec3f(0, 0, 1), Point3f(1, 0, 0), 1.2, Infinity), double(Infinity));
}

TEST(TimeGate, ReachOverLightsIsTheFarthestAndPastGateTheNearest) {
  OplGate gate;
  gate.start = 1.0;
  gate.end = 6.0;
  LightBound lights;
  lights.anywhere = false;
  lights.points[lights.count++] = Point3f(0.0f, 1.0f, 0.0f);
  lights.points[lights.count++] = Point3f(0.0f, 0.0f, 3.0f);
  Ray ray(Point3f(0.0f), Vec3f(0, 0, 1));
  // From OPL 2 at eta 1.5, 4 left: the light ahead at 3 is within reach up
  // to 1.5 t + |3 - t| = 4 (t = 2), the one aside up to 1.5 t + sqrt(1 + t^2) = 4 (t ~ 1.48).
  double reach = gateReach(ray, 1.5, 2.0, gate, lights);
  EXPECT_NEAR(
      reach,
      std::max(bisect(ray.o, ray.d, lights.points[0], 4.0, 1.5), bisect(ray.o, ray.d, lights.points[1], 4.0, 1.5)),
      1e-6);
  EXPECT_NEAR(reach, 2.0, 1e-6);
  EXPECT_EQ(gateReach(ray, 1.5, -Infinity, gate, lights), double(Infinity)) << "OPL not counted: no truncation";
  EXPECT_EQ(gateReach(ray, 0.8, 2.0, gate, lights), double(Infinity)) << "eta < 1: no bound";
  EXPECT_EQ(gateReach(ray, 1.0, 7.0, gate, lights), 0.0);
  EXPECT_FALSE(pastGate(Point3f(0.0f, 0.0f, 2.5f), 5.4, gate, lights));  // 0.5 from the light ahead
  EXPECT_TRUE(pastGate(Point3f(0.0f, 0.0f, 2.5f), 5.5, gate, lights));
  lights.anywhere = true;  // e.g. an area light as well: only the residual OPL bounds
  EXPECT_NEAR(gateReach(ray, 1.5, 2.0, gate, lights), 4.0 / 1.5, 1e-12);
  EXPECT_FALSE(pastGate(Point3f(5.0f), 5.9, gate, lights));
  EXPECT_TRUE(pastGate(Point3f(5.0f), 6.0, gate, lights));
}
