// The derived beam radius's bounds (radius_rule.h): the segment distance the
// density bound ranks against brute force, the k-nearest count, the time and
// boundary radii against their formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <femto/math/pcg32.h>
#include <transient_beams/radius_rule.h>

namespace femto::beams {
namespace {

Vec3f randomDirection(PCG32& rng) {
  float z = 1.0f - 2.0f * rng.nextFloat(), phi = 6.2831853f * rng.nextFloat(), s = std::sqrt(1.0f - z * z);
  return Vec3f(s * std::cos(phi), s * std::sin(phi), z);
}

TEST(RadiusRule, SegmentDistanceIsTheBruteForceMinimum) {
  PCG32 rng(3, 9);
  for (int i = 0; i < 300; ++i) {
    Point3f p0(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()), p1(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
    Vec3f d0 = randomDirection(rng), d1 = i % 5 == 0 ? d0 : randomDirection(rng);  // some parallel
    float l0 = i % 7 == 0 ? 0.0f : rng.nextFloat(), l1 = i % 11 == 0 ? 0.0f : rng.nextFloat();  // some points
    double best = 1e30;
    const int n = 400;
    for (int a = 0; a <= n; ++a)
      for (int b = 0; b <= n; ++b)
        best = std::min(best, double(distance(p0 + d0 * (l0 * a / n), p1 + d1 * (l1 * b / n))));
    const double d = segmentDistance(p0, d0, l0, p1, d1, l1);
    EXPECT_LE(d, best + 1e-6) << i;
    EXPECT_GE(d, best - 2e-3) << i;  // the grid's resolution
  }
}

TEST(RadiusRule, DensityRadiusCountsTheTargetPairsPerProbe) {
  // Beams parallel to z at known distances 1, 2, ..., 100 from one probe
  // along x: 5 pairs per probe are within the 5th distance.
  std::vector<Beam> beams;
  for (int i = 1; i <= 100; ++i) {
    Beam b;
    b.origin = Point3f(0.5f, float(i), -1.0f), b.direction = Vec3f(0.0f, 0.0f, 1.0f), b.length = 2.0f;
    beams.push_back(b);
  }
  std::vector<ProbeSegment> probes(1);
  probes[0].segment.ray = Ray(Point3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f));
  probes[0].segment.tMax = 1.0f;
  EXPECT_NEAR(densityRadius(beams, probes, 5.0), 5.0, 1e-6);
  EXPECT_FALSE(std::isfinite(densityRadius(beams, probes, 101.0))) << "too few beams: no bound";
  EXPECT_FALSE(std::isfinite(densityRadius(beams, {}, 5.0))) << "no probes: no bound";
  // Beams of another medium do not count.
  int other = 0;
  for (Beam& b : beams) b.medium = reinterpret_cast<const Medium*>(&other);
  EXPECT_FALSE(std::isfinite(densityRadius(beams, probes, 5.0)));
}

TEST(RadiusRule, TimeAndBoundaryRadiiFollowTheirFormulas) {
  TimeGrid grid;
  grid.bins = 100, grid.binWidth = 0.03;
  EXPECT_NEAR(timeRadius(grid, 1.5), TimeBinFraction * 0.03 / (2 * 1.5), 1e-12);
  EXPECT_FALSE(std::isfinite(timeRadius(TimeGrid{}, 1.5))) << "steady films: no bound";
  std::vector<ProbeSegment> probes(2);
  probes[0].segment.tMax = 1.0f, probes[1].segment.tMax = 3.0f;
  EXPECT_NEAR(boundaryRadius(probes), BoundaryBiasTarget * 2.0 / BoundaryLossPerRadius, 1e-12);
  EXPECT_NEAR(boundaryRadius(probes, true), BoundaryBiasTarget * 2.0 / (BoundaryLossPerRadius * BoundaryLossLeft),
              1e-12)
      << "beams extended past boundaries leave BoundaryLossLeft of the loss";
  EXPECT_FALSE(std::isfinite(boundaryRadius({})));
}

}  // namespace
}  // namespace femto::beams
