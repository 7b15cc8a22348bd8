// Time-gated distance ranges (transport/time_gate.h) against bisection on
// the path length g(t) = t + |o + t d - c|, and equiangular sampling of a
// part [tStart, tEnd] of a segment: its density integrates to one there and
// its samples stay in it.
#include <gtest/gtest.h>

#include <cmath>

#include <femto/math/pcg32.h>
#include <femto/math/warp.h>
#include <femto/transport/equiangular.h>
#include <femto/transport/time_gate.h>

using namespace femto;

namespace {

double pathLength(const Point3f& o, const Vec3f& d, const Point3f& c, double t) {
  return t + double(distance(o + d * float(t), c));
}

/// The t with pathLength = length, by bisection (g is non-decreasing).
double bisect(const Point3f& o, const Vec3f& d, const Point3f& c, double length) {
  double lo = 0.0, hi = 1.0;
  while (pathLength(o, d, c, hi) < length) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    double mid = 0.5 * (lo + hi);
    (pathLength(o, d, c, mid) < length ? lo : hi) = mid;
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
