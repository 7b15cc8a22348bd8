// The ray x photon point estimator (transient_beams/ray_point.h): the 2D
// kernel 1/(pi r^2) across the camera segment, the projection where the
// estimate is evaluated, the single arrival OPL, and the hard cases -- a
// photon exactly on the ray, at either end of the segment, an unbounded
// segment, degenerate and non-finite input, fuzzed pairs over many scales.
// References: closed forms in double, and a Monte Carlo check that the kernel
// integrates to 1 over the plane across the ray (5 sigma).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <femto/math/constants.h>
#include <femto/math/pcg32.h>
#include <transient_beams/ray_point.h>

namespace femto::beams {
namespace {

constexpr double DoublePi = 3.14159265358979323846;
constexpr float NaN = std::numeric_limits<float>::quiet_NaN();

CameraSegment segmentOf(Point3f o, Vec3f d, float tMax, float eta = 1.0f) {
  CameraSegment s;
  s.ray = Ray(o, normalize(d));
  s.tMax = tMax;
  s.eta = eta;
  return s;
}

Beam pointAt(Point3f p) {
  Beam b;
  b.origin = p;
  b.direction = Vec3f(0.0f, 0.0f, 1.0f);
  b.length = 0.0f;
  return b;
}

/// Every field finite, the kernel the disc's, the geometry collapsed on tRay.
void expectContract(const CameraSegment& s, const RayBeamHit& h, float r) {
  EXPECT_TRUE(std::isfinite(h.tRay) && std::isfinite(h.kernel) && std::isfinite(h.oplBegin));
  EXPECT_GE(h.tRay, 0.0f);
  EXPECT_LE(h.tRay, s.tMax);
  EXPECT_EQ(h.tRayBegin, h.tRay);
  EXPECT_EQ(h.tRayEnd, h.tRay);
  EXPECT_EQ(h.tBeam, 0.0f);
  EXPECT_EQ(h.oplBegin, h.oplEnd);
  EXPECT_NEAR(h.kernel, 1.0 / (DoublePi * double(r) * r), 1e-6 * h.kernel);
}

TEST(RayPoint, GenericPairIsTheDiscKernelAtTheProjection) {
  // A rotated segment; photons at distances 0 .. 0.99 r from it.
  const Vec3f d = normalize(Vec3f(0.3f, -0.5f, 0.8f));
  const Vec3f side = normalize(cross(d, Vec3f(0.0f, 0.0f, 1.0f)));
  const Point3f o(1.0f, 2.0f, -0.5f);
  const float r = 0.05f, eta = 1.33f;
  CameraSegment s = segmentOf(o, d, 6.0f, eta);
  for (float t : {0.5f, 2.0f, 5.9f})
    for (float offset : {0.0f, 0.02f, -0.0495f}) {
      RayBeamHit h;
      ASSERT_TRUE(rayPointIntersect(s, pointAt(o + d * t + side * offset), r, h)) << t << " " << offset;
      expectContract(s, h, r);
      EXPECT_NEAR(h.tRay, t, 1e-5);
      // The camera OPL to the projection plus the gap to the photon at its eta (1 here).
      EXPECT_NEAR(h.oplBegin, double(eta) * t + std::abs(offset), 1e-5);
    }
  RayBeamHit h;
  EXPECT_FALSE(rayPointIntersect(s, pointAt(o + d * 2.0f + side * 0.0505f), r, h)) << "just outside the radius";
  EXPECT_FALSE(rayPointIntersect(s, pointAt(o + d * -0.01f), r, h)) << "behind the segment's start";
  EXPECT_FALSE(rayPointIntersect(s, pointAt(o + d * 6.01f), r, h)) << "past the segment's end";
}

TEST(RayPoint, ObserverTimeOffCountsOnlyTheGap) {
  // Observer time off: no camera OPL; the photon still crosses the gap to
  // the ray (causality: light is not at ray(t) before it could get there).
  CameraSegment s = segmentOf(Point3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 3.0f, 0.0f);
  RayBeamHit h;
  Beam photon = pointAt(Point3f(0.01f, 0.0f, 2.0f));
  photon.eta = 1.5f;
  ASSERT_TRUE(rayPointIntersect(s, photon, 0.05f, h));
  EXPECT_NEAR(h.oplBegin, 1.5 * 0.01, 1e-7);
  EXPECT_EQ(h.oplEnd, h.oplBegin);
}

TEST(RayPoint, PhotonExactlyOnTheRayOrAtASegmentEndIsAFiniteHit) {
  const float r = 0.02f;
  // Axis-aligned: the ends are exact in float.
  CameraSegment s = segmentOf(Point3f(0.5f, -1.0f, 2.0f), Vec3f(0.0f, 1.0f, 0.0f), 4.0f);
  for (float t : {0.0f, 1.25f, 4.0f}) {
    RayBeamHit h;
    ASSERT_TRUE(rayPointIntersect(s, pointAt(s.ray(t)), r, h)) << "t " << t;
    expectContract(s, h, r);
    EXPECT_EQ(h.tRay, t);
  }
  // Rotated: the ends round either way; a miss or a hit obeying the contract.
  PCG32 rng(3, 9);
  for (int i = 0; i < 1000; ++i) {
    Vec3f d(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);
    if (!(length(d) > 1e-3f)) continue;
    CameraSegment rs = segmentOf(Point3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()), d, 1.0f + rng.nextFloat());
    for (float t : {0.0f, 0.5f * rs.tMax, rs.tMax}) {
      RayBeamHit h;
      bool hit = rayPointIntersect(rs, pointAt(rs.ray(t)), r, h);
      if (t > 0.0f && t < rs.tMax) EXPECT_TRUE(hit) << "on the ray inside the segment";
      if (hit) expectContract(rs, h, r);
    }
  }
}

TEST(RayPoint, UnboundedSegmentFindsFarPhotons) {
  CameraSegment s = segmentOf(Point3f(0.0f), Vec3f(1.0f, 1.0f, 0.0f), Infinity);
  RayBeamHit h;
  ASSERT_TRUE(rayPointIntersect(s, pointAt(s.ray(1000.0f) + Vec3f(0.0f, 0.0f, 0.01f)), 0.05f, h));
  EXPECT_NEAR(h.tRay, 1000.0f, 1e-2);
  EXPECT_TRUE(std::isfinite(h.oplBegin));
}

TEST(RayPoint, DegenerateInputIsAMiss) {
  const CameraSegment good = segmentOf(Point3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 2.0f);
  const Beam near = pointAt(Point3f(0.01f, 0.0f, 1.0f));
  RayBeamHit h;
  for (float r : {0.0f, -0.1f, NaN, Infinity, 1e-30f}) EXPECT_FALSE(rayPointIntersect(good, near, r, h)) << "radius " << r;
  for (float tMax : {0.0f, -1.0f, NaN}) {
    CameraSegment s = good;
    s.tMax = tMax;
    EXPECT_FALSE(rayPointIntersect(s, near, 0.05f, h)) << "tMax " << tMax;
  }
  CameraSegment nanOrigin = good, nanDirection = good, zeroDirection = good;
  nanOrigin.ray.o = Point3f(NaN, 0.0f, 0.0f);
  nanDirection.ray.d = Vec3f(0.0f, NaN, 1.0f);
  zeroDirection.ray.d = Vec3f(0.0f);
  EXPECT_FALSE(rayPointIntersect(nanOrigin, near, 0.05f, h));
  EXPECT_FALSE(rayPointIntersect(nanDirection, near, 0.05f, h));
  EXPECT_FALSE(rayPointIntersect(zeroDirection, near, 0.05f, h)) << "no direction";
  EXPECT_FALSE(rayPointIntersect(good, pointAt(Point3f(NaN, 0.0f, 1.0f)), 0.05f, h));
  EXPECT_FALSE(rayPointIntersect(good, pointAt(Point3f(Infinity, 0.0f, 1.0f)), 0.05f, h));
}

TEST(RayPoint, KernelIntegratesToOneAcrossTheRay) {
  // A unit density of photons in a box around the segment (cross-section
  // A = (2a)^2 > pi r^2, projections on [0.5, 1.5]), each carrying volume / n:
  // the estimate of the density integrated along the segment must be the
  // box's length along it, 1. Per photon the expectation is
  // P(hit) kernel A l = (pi r^2 / A)(1 / pi r^2) A l = l.
  PCG32 rng(17, 5);
  const Vec3f d = normalize(Vec3f(0.2f, 0.9f, -0.4f));
  const Vec3f u = normalize(cross(d, Vec3f(1.0f, 0.0f, 0.0f))), v = cross(d, u);
  const Point3f o(0.3f, 0.1f, 0.7f);
  const float r = 0.1f, a = 0.15f, tMax = 2.0f;
  const double boxLength = 1.0;  // projections uniform on [0.5, 1.5], inside [0, tMax]
  CameraSegment s = segmentOf(o, d, tMax);
  const int n = 200000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    float t = 0.5f + rng.nextFloat(), x = a * (2.0f * rng.nextFloat() - 1.0f), y = a * (2.0f * rng.nextFloat() - 1.0f);
    RayBeamHit h;
    double w = rayPointIntersect(s, pointAt(o + d * t + u * x + v * y), r, h) ? h.kernel * (4.0 * a * a * boxLength) : 0.0;
    sum += w, sum2 += w * w;
  }
  double mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / n);
  EXPECT_NEAR(mean, boxLength, 5.0 * se) << "the density's integral along the segment";
}

TEST(RayPoint, FuzzedPairsMissOrHitWithinTheContract) {
  PCG32 rng(99, 2);
  int hits = 0;
  for (int i = 0; i < 100000; ++i) {
    float scale = std::pow(10.0f, 6.0f * rng.nextFloat() - 3.0f);
    Vec3f d(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);
    if (!(length(d) > 1e-4f)) continue;
    Point3f o(scale * (rng.nextFloat() - 0.5f), scale * (rng.nextFloat() - 0.5f), scale * (rng.nextFloat() - 0.5f));
    CameraSegment s = segmentOf(o, d, rng.nextFloat() < 0.1f ? Infinity : scale * rng.nextFloat());
    float r = scale * 0.1f * rng.nextFloat();
    Point3f p = s.ray(scale * (1.2f * rng.nextFloat() - 0.1f)) +
                Vec3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f) * (0.3f * scale);
    RayBeamHit h;
    if (!rayPointIntersect(s, pointAt(p), r, h)) continue;
    ++hits;
    expectContract(s, h, r);
    if (::testing::Test::HasFailure()) FAIL() << "pair " << i;
  }
  EXPECT_GT(hits, 1000);
}

}  // namespace
}  // namespace femto::beams
