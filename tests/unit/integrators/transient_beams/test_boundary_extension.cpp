// Beams extended past the boundary of their medium (boundary_extension.h):
// a uniform field of parallel beams in the half-space z < 0, hitting the
// wall z = 0 at 45 degrees (or leaving it), seen by a camera segment that
// ends on the wall. The expected sum of the exact (cylinder) kernel over the
// beams is the beams' areal density times the segment's length when the
// blurred density is right up to the wall: with the extensions it must be,
// within 5 standard errors (no bias is left for a planar wall and a uniform
// field); without them it must be low by the first-order loss.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <femto/math/pcg32.h>
#include <transient_beams/boundary_extension.h>
#include <transient_beams/ray_beam.h>

#include "media_test_util.h"

namespace femto::beams {
namespace {

struct Estimate {
  double mean = 0.0, error = 0.0;
};

/// Sum over beams of the cylinder kernel for one camera segment from z = -1
/// to the wall along +z, divided by density x length (1 when unbiased).
/// `leaving`: beams start on the wall and run into the medium.
Estimate wallEstimate(bool extend, bool leaving) {
  const float r = 0.1f;
  const Vec3f v = normalize(Vec3f(1.0f, 0.0f, -1.0f) * (leaving ? 1.0f : -1.0f));  // light's direction
  const Vec3f e1(0.0f, 1.0f, 0.0f), e2 = normalize(cross(v, e1));
  const Normal3f n(0.0f, 0.0f, 1.0f);
  CameraSegment seg;
  seg.ray = Ray(Point3f(0.0f, 0.0f, -1.0f), Vec3f(0.0f, 0.0f, 1.0f));
  seg.tMax = 1.0f;
  // Offsets across the beams, uniform on the rectangle of lines that can
  // pass within r of the segment (its shadow along v, padded by 2r): every
  // other line misses it, so the density is the count over that area.
  const float b0 = std::min(dot(Vec3f(0.0f, 0.0f, -1.0f), e2), 0.0f) - 2.0f * r;
  const float b1 = std::max(dot(Vec3f(0.0f, 0.0f, -1.0f), e2), 0.0f) + 2.0f * r;
  const float a0 = -2.0f * r, a1 = 2.0f * r;
  const int count = 1600000;
  const double density = count / (double(a1 - a0) * double(b1 - b0));
  PCG32 rng(7, 11);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < count; ++i) {
    const Vec3f q = e1 * (a0 + (a1 - a0) * rng.nextFloat()) + e2 * (b0 + (b1 - b0) * rng.nextFloat());
    const Point3f onWall = Point3f(0.0f) + q - v * (q.z / v.z);  // the line through q meets z = 0 here
    Beam b;
    b.direction = v;
    b.length = 6.0f;
    // Arriving: from 6 deep up to the wall; leaving: from the wall 6 deep.
    b.origin = leaving ? onWall : onWall - v * b.length;
    (leaving ? b.before : b.after) = extend ? boundaryExtension(n, v) : 0.0f;
    RayBeamHit hit;
    if (!rayBeamIntersect(seg, b, r, hit, RayBeamKernel::Cylinder)) continue;
    sum += hit.kernel;
    sum2 += double(hit.kernel) * hit.kernel;
  }
  // Each beam's term is independent: the variance of the sum is about sum2.
  return {sum / density, std::sqrt(sum2) / density};
}

TEST(BoundaryExtension, RestoresTheDensityAtAPlanarWall) {
  for (bool leaving : {false, true}) {
    const Estimate with = wallEstimate(true, leaving), without = wallEstimate(false, leaving);
    // First-order loss of the disc kernel at one end (radius_rule.h): up to
    // 2 r / (3 pi) of the density per unit length, 0.021 here, less for
    // the disc's tilt (45 degrees: 0.015).
    std::printf("%s: with extension %.4f +- %.4f, without %.4f +- %.4f\n", leaving ? "leaving" : "arriving", with.mean,
                with.error, without.mean, without.error);
    EXPECT_NEAR(with.mean, 1.0, 5.0 * with.error) << (leaving ? "leaving" : "arriving");
    EXPECT_LT(without.mean, 1.0 - 5.0 * without.error) << "the loss the extension corrects must show";
  }
}

TEST(BoundaryExtension, IsTheInverseCosineUpToItsCap) {
  const Normal3f n(0.0f, 0.0f, 1.0f);
  EXPECT_FLOAT_EQ(boundaryExtension(n, Vec3f(0.0f, 0.0f, -1.0f)), 1.0f);
  EXPECT_NEAR(boundaryExtension(n, normalize(Vec3f(1.0f, 0.0f, 1.0f))), std::sqrt(2.0f), 1e-5f);
  EXPECT_FLOAT_EQ(boundaryExtension(n, Vec3f(1.0f, 0.0f, 0.0f)), MaxBoundaryExtension);
  EXPECT_FLOAT_EQ(boundaryExtension(n * 3.0f, Vec3f(0.0f, 0.0f, 1.0f)), 1.0f) << "the normal's length does not matter";
}

// Light crossing a plane of normal n along d without turning, from index 1
// into index eta: a point x on the far side at depth lambda(x) = n.(x - b) /
// (n.d) along d was reached at OPL s(x) + (eta - 1) lambda(x) after b (plane
// wave). boundaryOffsetDelay must give that as eta s(x) + offsetDelay.(x - b).
TEST(BoundaryExtension, OffsetDelayIsThePlaneWavesTilt) {
  PCG32 rng(5, 11);
  for (int i = 0; i < 1000; ++i) {
    const Vec3f n = normalize(Vec3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f));
    Vec3f d = normalize(Vec3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f));
    if (dot(n, d) < 0.0f) d = -d;
    if (1.0f / dot(n, d) > 0.95f * MaxBoundaryExtension) continue;  // the cap (below)
    const float eta = 1.0f + rng.nextFloat();
    const Vec3f delay = boundaryOffsetDelay(n, d, eta - 1.0f);
    EXPECT_NEAR(dot(delay, d), 0.0f, 1e-4f) << "the tilt lies across the beam";
    const Vec3f x(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);  // b = 0
    const double lambda = double(dot(n, x)) / double(dot(n, d)), s = dot(x, d);
    EXPECT_NEAR(eta * s + dot(delay, x), s + (eta - 1.0) * lambda, 2e-4 * (1.0 + std::abs(lambda)));
  }
  const Vec3f n(0.0f, 0.0f, 1.0f);
  EXPECT_EQ(length(boundaryOffsetDelay(n, normalize(Vec3f(1.0f, 0.0f, 1.0f)), 0.0f)), 0.0f) << "no index change";
  const Vec3f grazing = boundaryOffsetDelay(n, Vec3f(1.0f, 0.0f, 0.0f), 0.5f);
  EXPECT_NEAR(length(grazing), 0.5f * std::sqrt(MaxBoundaryExtension * MaxBoundaryExtension - 1.0f), 1e-3f)
      << "tan theta_n capped as the extension is";
}

// The density an extension carries continues the beam's attenuation past
// the end it extends: rising before the start, falling past the end, in
// every channel; media whose sigma_t is not one number keep the end's value.
TEST(BoundaryExtension, ContinuesTheBeamsAttenuation) {
  auto fog = test::sceneWithMedium(
      R"(<medium type="homogeneous" id="m"><rgb name="sigma_t" value="0.5, 1, 2"/><rgb name="albedo" value="0.5"/></medium>)");
  const Medium& m = *fog->sensor().medium();
  const Color3f before = extensionContinuation(m, -0.1f), after = extensionContinuation(m, 0.1f);
  EXPECT_NEAR(before.r, std::exp(0.05f), 1e-6f);
  EXPECT_NEAR(before.b, std::exp(0.2f), 1e-6f);
  EXPECT_NEAR(after.g, std::exp(-0.1f), 1e-6f);
  EXPECT_EQ(extensionContinuation(m, 0.0f).g, 1.0f) << "on the beam itself";
  const auto dir = test::scratchDir("extension-continuation");
  test::writeDensityGrid(dir / "density.vol", 3, 1.0f);
  auto grid = test::sceneWithMedium(R"(<medium type="heterogeneous" id="m">
    <volume name="sigma_t" type="gridvolume"><string name="filename" value="density.vol"/></volume></medium>)",
                                    "3.0.0", dir);
  EXPECT_EQ(extensionContinuation(*grid->sensor().medium(), -0.1f).r, 1.0f) << "heterogeneous: the end's density";
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace femto::beams
