// SurfacePhotonMap: radius queries equal brute force exactly (the same
// inclusive test |x - p|^2 <= r^2), for photons on surfaces and in volume,
// small and large radii, both constructors; empty maps; every photon in one
// cell; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <tbb/parallel_for.h>

#include <femto/base/error.h>
#include <femto/math/constants.h>
#include <femto/math/pcg32.h>
#include <transient_beams/surface_photon_map.h>

namespace femto::beams {
namespace {

SurfacePhoton photonAt(const Point3f& p) {
  SurfacePhoton ph;
  ph.p = p;
  return ph;
}

/// Photons on the six faces of the unit cube (the walls of a box scene),
/// plus a few in its volume.
std::vector<SurfacePhoton> wallPhotons(PCG32& rng, size_t n) {
  std::vector<SurfacePhoton> photons;
  for (size_t i = 0; i < n; ++i) {
    Point3f p(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
    if (i % 10 != 0) p[int(rng.nextUInt(3))] = rng.nextUInt(2) ? 1.0f : 0.0f;
    photons.push_back(photonAt(p));
  }
  return photons;
}

std::vector<uint32_t> bruteForce(const std::vector<SurfacePhoton>& photons, const Point3f& p, float radius) {
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < photons.size(); ++i)
    if (squaredLength(photons[i].p - p) <= radius * radius) out.push_back(i);
  return out;
}

void expectSameAsBruteForce(const SurfacePhotonMap& map, const Point3f& p, float radius) {
  std::vector<uint32_t> found;
  map.query(p, radius, found);
  std::sort(found.begin(), found.end());
  EXPECT_EQ(found, bruteForce(map.photons(), p, radius)) << "at " << p << " radius " << radius;
}

TEST(SurfacePhotonMap, EqualsBruteForce) {
  PCG32 rng(1, 2);
  std::vector<SurfacePhoton> photons = wallPhotons(rng, 20000);
  SurfacePhotonMap guessed(photons), sized(photons, 0.02f);
  EXPECT_NEAR(sized.cellSize(), 0.02f, 1e-7f);
  // Radii around, below and far above the cell size (the last scans all).
  for (float radius : {0.0f, 0.005f, 0.02f, 0.05f, 0.3f, 3.0f})
    for (int i = 0; i < 40; ++i) {
      // Query points on the walls, in the volume and outside the photons' box.
      Point3f p(1.4f * rng.nextFloat() - 0.2f, 1.4f * rng.nextFloat() - 0.2f, 1.4f * rng.nextFloat() - 0.2f);
      if (i % 2) p = photons[rng.nextUInt(uint32_t(photons.size()))].p;
      expectSameAsBruteForce(guessed, p, radius);
      expectSameAsBruteForce(sized, p, radius);
    }
}

TEST(SurfacePhotonMap, PhotonsExactlyAtTheRadiusCount) {
  SurfacePhotonMap map({photonAt({0.3f, 0, 0}), photonAt({0, -0.25f, 0}), photonAt({0, 0, 0.3001f})}, 0.01f);
  std::vector<uint32_t> out;
  map.query({0, 0, 0}, 0.3f, out);
  std::sort(out.begin(), out.end());
  EXPECT_EQ(out, (std::vector<uint32_t>{0, 1}));
}

TEST(SurfacePhotonMap, EmptyMaps) {
  std::vector<uint32_t> out{7};
  SurfacePhotonMap none;
  none.query({0, 0, 0}, 1.0f, out);
  EXPECT_TRUE(out.empty());
  SurfacePhotonMap empty(std::vector<SurfacePhoton>{}, 0.1f);
  out = {7};
  empty.query({0, 0, 0}, 1.0f, out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(empty.size(), 0u);
}

TEST(SurfacePhotonMap, AllPhotonsInOneCell) {
  PCG32 rng(5, 5);
  std::vector<SurfacePhoton> cluster, point;
  for (int i = 0; i < 2000; ++i) {
    cluster.push_back(photonAt(Point3f(0.5f) + Vec3f(rng.nextFloat(), rng.nextFloat(), 0.0f) * 1e-3f));
    point.push_back(photonAt(Point3f(0.25f, 0.5f, 0.75f)));
  }
  SurfacePhotonMap clusterMap(cluster, 0.1f), clusterGuess(cluster), pointMap(point, 0.1f), pointGuess(point);
  for (float radius : {0.0f, 2e-4f, 5e-4f, 0.01f}) {
    for (int i = 0; i < 10; ++i) {
      Point3f p = Point3f(0.5f) + Vec3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 1.2e-3f;
      expectSameAsBruteForce(clusterMap, p, radius);
      expectSameAsBruteForce(clusterGuess, p, radius);
    }
    expectSameAsBruteForce(pointMap, {0.25f, 0.5f, 0.75f}, radius);
    expectSameAsBruteForce(pointGuess, {0.25f, 0.5f, 0.75f}, radius);
    expectSameAsBruteForce(pointGuess, {0.25f, 0.5f, 0.76f}, radius);
  }
}

TEST(SurfacePhotonMap, ConcurrentQueriesAreDeterministic) {
  PCG32 rng(9, 9);
  std::vector<SurfacePhoton> photons = wallPhotons(rng, 5000);
  SurfacePhotonMap map(photons, 0.03f), again(photons, 0.03f);
  std::vector<Point3f> points;
  for (int i = 0; i < 500; ++i) points.push_back(photons[rng.nextUInt(5000)].p);
  std::vector<std::vector<uint32_t>> serial(points.size()), parallel(points.size());
  for (size_t i = 0; i < points.size(); ++i) map.query(points[i], 0.03f, serial[i]);
  tbb::parallel_for(size_t(0), points.size(), [&](size_t i) { again.query(points[i], 0.03f, parallel[i]); });
  EXPECT_EQ(serial, parallel);  // same photons, same order
}

TEST(SurfacePhotonMap, RejectsBadInput) {
  EXPECT_THROW(SurfacePhotonMap({photonAt({0, 0, 0})}, 0.0f), Error);
  EXPECT_THROW(SurfacePhotonMap({photonAt({0, 0, 0})}, std::nanf("")), Error);
  try {
    SurfacePhotonMap map({photonAt({0, 0, 0}), photonAt({Infinity, 0, 0})}, 0.1f);
    FAIL() << "a photon at infinity was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("photon 1"), std::string::npos) << e.what();
  }
  std::vector<uint32_t> out{1};
  SurfacePhotonMap map({photonAt({0, 0, 0})}, 0.1f);
  map.query({0, 0, 0}, std::nanf(""), out);
  EXPECT_TRUE(out.empty());
  map.query({0, 0, 0}, -1.0f, out);
  EXPECT_TRUE(out.empty());
}

}  // namespace

TEST(SurfacePhotonMap, LastLegDelayIsTheOplThroughTheLegsStart) {
  // eta (|x - q| - leg) against the same in long double, from a leg of 1e-3
  // to 1e4 and offsets down to 1e-6 (where the difference of two lengths
  // would cancel in float); the plane-wave limit for an infinite leg; no
  // correction without a known leg. The reference takes q along wi made unit
  // in long double: the float wi is unit only to ~1e-7, which would move q by
  // that much of the leg.
  SurfacePhoton photon;
  photon.p = Point3f(0.3f, -0.2f, 1.0f);
  photon.wi = normalize(Vec3f(0.4f, 0.5f, 0.7f));
  photon.legEta = 1.33f;
  const long double w[3] = {photon.wi.x, photon.wi.y, photon.wi.z};
  const long double norm = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  PCG32 rng(3, 5);
  for (float leg : {1e-3f, 0.5f, 3.0f, 1e4f})
    for (float size : {1e-6f, 1e-3f, 0.1f}) {
      const Vec3f offset = Vec3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f) * size;
      const Point3f x = photon.p + offset;
      // x - p exactly (x is rounded to float).
      const long double o[3] = {(long double)x.x - photon.p.x, (long double)x.y - photon.p.y,
                                (long double)x.z - photon.p.z};
      long double toStart2 = 0.0L, along = 0.0L;
      for (int k = 0; k < 3; ++k) {
        const long double d = o[k] - w[k] / norm * leg;
        toStart2 += d * d;
        along += o[k] * w[k] / norm;
      }
      const double exact = double(1.33L * (std::sqrt(toStart2) - (long double)leg));
      photon.leg = leg;
      EXPECT_NEAR(lastLegDelay(photon, x), exact, 1e-12 + 1e-6 * std::fabs(exact))
          << "leg " << leg << ", offset " << size;
      photon.leg = Infinity;
      const double plane = double(-1.33L * along);
      EXPECT_NEAR(lastLegDelay(photon, x), plane, 1e-12 + 1e-6 * std::fabs(plane)) << "offset " << size;
    }
  photon.legEta = 0.0f;
  EXPECT_EQ(lastLegDelay(photon, photon.p + Vec3f(0.1f)), 0.0);
}

// Time gating (query's minOpl): the photons a gated query drops are exactly
// none of those whose light can reach the query point at or after minOpl
// (photon.opl + lastLegDelay at the point, legs finite, infinite and
// unknown), also at a threshold just below each such photon's arrival; and
// it does drop photons that arrive earlier.
TEST(SurfacePhotonMap, TimeGatedQueryKeepsEveryPhotonThatArrivesInTime) {
  PCG32 rng(9, 4);
  std::vector<SurfacePhoton> photons = wallPhotons(rng, 6000);
  for (size_t i = 0; i < photons.size(); ++i) {
    SurfacePhoton& ph = photons[i];
    ph.opl = 10.0 * rng.nextDouble();
    ph.wi = Vec3f(0.0f, 0.0f, 1.0f);
    ph.legEta = i % 4 == 0 ? 0.0f : 1.0f + 0.5f * rng.nextFloat();
    ph.leg = i % 7 == 0 ? Infinity : 0.01f + rng.nextFloat();
  }
  const float radius = 0.05f;
  SurfacePhotonMap map(photons, radius);
  std::vector<uint32_t> all, gated, edge;
  size_t dropped = 0, inTime = 0;
  for (int i = 0; i < 300; ++i) {
    const Point3f p = map.photons()[rng.nextUInt(uint32_t(map.size()))].p;
    const double minOpl = 10.0 * rng.nextDouble();
    map.query(p, radius, all);
    map.query(p, radius, gated, minOpl);
    std::sort(gated.begin(), gated.end());
    dropped += all.size() - gated.size();
    for (uint32_t k : all) {
      const double arrival = map.photons()[k].opl + lastLegDelay(map.photons()[k], p);
      if (arrival >= minOpl) {
        ++inTime;
        EXPECT_TRUE(std::binary_search(gated.begin(), gated.end(), k)) << "photon " << k << " arriving " << arrival;
      }
      map.query(p, radius, edge, arrival - 1e-6 * (std::abs(arrival) + 1.0));
      EXPECT_TRUE(std::find(edge.begin(), edge.end(), k) != edge.end()) << "photon " << k << " at its own arrival";
    }
  }
  ASSERT_GT(inTime, 500u);
  EXPECT_GT(dropped, 500u) << "the gate drops photons that arrive too early";
}

}  // namespace femto::beams
