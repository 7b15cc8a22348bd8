// The ray x beam estimator (transient_beams/ray_beam.h): the 1D kernel in the
// generic case, the exact chord where it is clipped, the OPL interval, and the
// hard cases -- near-parallel, anti-parallel, grazing, beams and camera
// segments ending inside the kernel, zero-length overlaps, degenerate input.
// References: closed forms for fixed geometry, a brute-force march through
// the kernel region (ray_beam_test_util.h), and Monte Carlo averages over the
// beam's lateral offset (5 sigma from the sample variance) against the
// numerically integrated blurred beam.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ray_beam_test_util.h"

namespace femto::beams {
namespace {

using test::hitContractHolds;
using test::makePair;
using test::marchOverlap;
using test::Pair;
using test::PairSpec;
using test::Rotation;

constexpr double DoublePi = 3.14159265358979323846;

RayBeamHit mustHit(const Pair& p, float r, RayBeamKernel k = RayBeamKernel::OneD) {
  RayBeamHit h;
  EXPECT_TRUE(rayBeamIntersect(p.segment, p.beam, r, h, k));
  EXPECT_TRUE(hitContractHolds(p, h));
  return h;
}

// --- Fixed geometry -------------------------------------------------------

TEST(RayBeam, OneDKernelIsTheClosedFormAtTheClosestApproach) {
  PCG32 rng(7, 1);
  const float r = 0.05f;
  for (double theta : {0.3, 0.8, 1.5707963, 2.2, 2.9}) {
    for (double offset : {0.0, 0.02, -0.049}) {
      PairSpec s;
      s.theta = theta, s.offset = offset, s.sClosest = 3, s.tClosest = 4, s.length = 7, s.tMax = 9;
      Pair p = makePair(s, Rotation(rng), {1.5, -2, 0.25});
      RayBeamHit h = mustHit(p, r);
      SCOPED_TRACE(testing::Message() << "theta " << theta << " offset " << offset);
      EXPECT_NEAR(h.kernel, 1.0 / (2 * r * std::sin(theta)), 2e-4 * h.kernel);
      EXPECT_NEAR(h.tRay, s.tClosest, 1e-4);
      EXPECT_NEAR(h.tBeam, s.sClosest, 1e-4);
      // The overlap is the chord of the cylinder, 2 sqrt(r^2 - d^2) / sin(theta) long.
      double chord = 2 * std::sqrt(r * r - offset * offset) / std::sin(theta);
      EXPECT_NEAR(h.tRayEnd - h.tRayBegin, chord, 1e-4 + 1e-4 * chord);
    }
  }
}

/// Pairs whose longest chord is clipped (by a beam end, the segment's end or
/// the segment's start), and near-parallel pairs: the kernel is the exact
/// chord / (pi r^2), checked against the march.
std::vector<std::pair<const char*, PairSpec>> clippedPairs() {
  std::vector<std::pair<const char*, PairSpec>> cases;
  PairSpec s;
  s.theta = 0.9, s.sClosest = 0.0, s.tClosest = 2, s.length = 3, s.tMax = 4, s.offset = 0.01;
  cases.push_back({"beam starts inside the kernel", s});
  s.sClosest = 3.0;
  cases.push_back({"beam ends inside the kernel", s});
  s.sClosest = 1.5, s.tClosest = 4.0;
  cases.push_back({"camera segment ends inside the kernel", s});
  s.tClosest = 0.0;
  cases.push_back({"camera starts inside the kernel", s});
  s = PairSpec{};
  s.theta = 1e-3, s.sClosest = 1.0, s.tClosest = 1.0, s.length = 2, s.tMax = 5, s.offset = 0.02;
  cases.push_back({"near-parallel", s});
  s.theta = DoublePi - 1e-3;
  cases.push_back({"near-anti-parallel", s});
  s.theta = 0.0;
  cases.push_back({"parallel", s});
  s.theta = DoublePi;
  cases.push_back({"anti-parallel", s});
  s.theta = 0.04, s.length = 1.0, s.tMax = 1.5;
  cases.push_back({"shallow, chord longer than both segments", s});
  return cases;
}

TEST(RayBeam, ClippedPairsGetTheExactChord) {
  PCG32 rng(8, 1);
  const float r = 0.05f;
  for (const auto& [name, spec] : clippedPairs()) {
    SCOPED_TRACE(name);
    Pair p = makePair(spec, Rotation(rng), {0.5, 0.5, -1});
    test::Overlap ref = marchOverlap(p, r, 400000);
    ASSERT_GT(ref.length, 0);
    for (RayBeamKernel k : {RayBeamKernel::OneD, RayBeamKernel::Cylinder}) {
      RayBeamHit h = mustHit(p, r, k);
      // Each end of the marched overlap is within one step of the true one.
      EXPECT_NEAR(h.kernel, ref.length / (DoublePi * r * r), 2 * ref.step / (DoublePi * r * r) + 1e-4 * h.kernel);
      EXPECT_NEAR(h.tRayBegin, ref.tFirst, ref.step + 1e-5);
      EXPECT_NEAR(h.tRayEnd, ref.tLast, ref.step + 1e-5);
      EXPECT_NEAR(h.tRay, 0.5 * (ref.tFirst + ref.tLast), ref.step + 1e-5);
      // tBeam is the projection of ray(tRay) on the beam.
      double sAtRay = 0;
      test::insideKernel(p, r, h.tRay, &sAtRay);
      EXPECT_NEAR(h.tBeam, std::clamp(sAtRay, 0.0, double(p.beam.length)), 1e-5);
    }
  }
}

TEST(RayBeam, CylinderKernelIsTheMarchedChordForRandomPairs) {
  PCG32 rng(9, 1);
  const float r = 0.1f;
  int hits = 0;
  for (int i = 0; i < 60; ++i) {
    PairSpec s;
    s.theta = DoublePi * rng.nextDouble();
    s.sClosest = 3 * rng.nextDouble() - 0.5, s.tClosest = 3 * rng.nextDouble() - 0.5;
    s.length = 0.2 + 2 * rng.nextDouble(), s.tMax = 0.2 + 2.5 * rng.nextDouble();
    s.offset = 0.12 * (2 * rng.nextDouble() - 1);
    Pair p = makePair(s, Rotation(rng));
    test::Overlap ref = marchOverlap(p, r, 100000);
    RayBeamHit h;
    bool hit = rayBeamIntersect(p.segment, p.beam, r, h, RayBeamKernel::Cylinder);
    // A march may miss an overlap shorter than two steps, and vice versa.
    if (hit != (ref.length > 0)) {
      EXPECT_LT(hit ? h.tRayEnd - h.tRayBegin : ref.length, 2 * ref.step) << i;
      continue;
    }
    if (!hit) continue;
    ++hits;
    EXPECT_TRUE(hitContractHolds(p, h));
    EXPECT_NEAR(h.kernel * DoublePi * r * r, ref.length, 2 * ref.step + 1e-5) << i;
  }
  EXPECT_GT(hits, 15);
}

// --- Unbiasedness over the lateral offset ---------------------------------

struct OffsetCase {
  const char* name;
  PairSpec spec;
};

std::vector<OffsetCase> offsetCases() {
  std::vector<OffsetCase> cases;
  PairSpec s;
  s.theta = 1.1, s.sClosest = 2, s.tClosest = 2, s.length = 4, s.tMax = 4;
  cases.push_back({"generic", s});
  s.theta = 0.05, s.sClosest = 5, s.tClosest = 5, s.length = 10, s.tMax = 10;
  cases.push_back({"grazing (3 degrees), 1D kernel still fits", s});
  s.theta = DoublePi - 0.05;
  cases.push_back({"grazing anti-parallel", s});
  s.theta = 0.02, s.sClosest = 1, s.tClosest = 1, s.length = 2, s.tMax = 3;
  cases.push_back({"near-parallel, chord clipped", s});
  s.theta = 1e-4;
  cases.push_back({"near-parallel 1e-4", s});
  s.theta = 0.0;
  cases.push_back({"parallel", s});
  s.theta = DoublePi;
  cases.push_back({"anti-parallel", s});
  s = PairSpec{};
  s.theta = 0.7, s.sClosest = 0.01, s.tClosest = 2, s.length = 3, s.tMax = 4;
  cases.push_back({"beam starts inside the kernel", s});
  s.sClosest = 2.97;
  cases.push_back({"beam ends inside the kernel", s});
  s.sClosest = 1.5, s.tClosest = 3.98;
  cases.push_back({"camera segment ends inside the kernel", s});
  s.tClosest = 0.03;
  cases.push_back({"camera starts inside the kernel", s});
  return cases;
}

// The 1D estimate is not the blurred beam's line integral offset by offset,
// only on average over the offset d along the common normal:
// E_d[kernel] = (1 / 2r) int_{-r}^{r} chord(d) / (pi r^2) dd. The right side
// is integrated numerically (midpoint rule in d, marched chords). Offsets
// beyond r only add misses (tested below): with |d| < r the 1D kernel has no
// variance, so even a small bias shows.
TEST(RayBeam, OffsetAverageMatchesTheBlurredBeam) {
  const float r = 0.05f;
  const double R = r;
  PCG32 rng(10, 1);
  for (const OffsetCase& c : offsetCases()) {
    SCOPED_TRACE(c.name);
    Rotation rot(rng);
    // Reference: 200 offsets x 40000-step marches over the segment.
    const int nd = 200;
    double ref = 0, marchErr = 0;
    for (int i = 0; i < nd; ++i) {
      PairSpec s = c.spec;
      s.offset = -R + (i + 0.5) * (2 * R / nd);
      test::Overlap o = marchOverlap(makePair(s, rot), r, 40000);
      ref += o.length / (DoublePi * r * r) / nd;
      marchErr = std::max(marchErr, 2 * o.step / (DoublePi * r * r));
    }
    // The chord's sqrt edge at |d| = r limits the midpoint rule in d to
    // O(h^1.5) relative: bound it by one chord's worth of a cell.
    double quadErr = ref * 2 * std::pow(1.0 / nd, 1.5);
    // Monte Carlo over uniform offsets.
    const int n = 20000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      PairSpec s = c.spec;
      s.offset = R * (2 * rng.nextDouble() - 1);
      Pair p = makePair(s, rot);
      RayBeamHit h;
      double k = 0;
      if (rayBeamIntersect(p.segment, p.beam, r, h)) {
        EXPECT_TRUE(hitContractHolds(p, h));
        k = h.kernel;
      }
      sum += k, sum2 += k * k;
    }
    double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, ref, 5 * sigma + marchErr + quadErr + 1e-6 * ref) << "sigma " << sigma;
  }
}

// Offsets spread over the whole plane perpendicular to the beam (square of
// side S covering the segment's footprint) also move the closest approach
// along the ray, switching pairs between the 1D and the chord kernel. The
// blurred beam's integral over all offsets is the length of the camera
// segment between the beam's end planes (the disc kernel integrates to 1),
// so E[kernel] = slabLength / S^2 exactly.
TEST(RayBeam, PlaneOffsetAverageConservesTheBeam) {
  const float r = 0.05f;
  PCG32 rng(11, 1);
  for (const OffsetCase& c : offsetCases()) {
    SCOPED_TRACE(c.name);
    const PairSpec& base = c.spec;
    // In the pair's frame the beam is the x axis from -sClosest to
    // length - sClosest; the segment's slab part is where x(t) is in it.
    double cx = std::cos(base.theta), sy = std::sin(base.theta);
    double t0 = 0, t1 = base.tMax;
    if (std::abs(cx) > 1e-12) {
      double a = (-base.sClosest / cx) + base.tClosest, b = ((base.length - base.sClosest) / cx) + base.tClosest;
      t0 = std::max(t0, std::min(a, b)), t1 = std::min(t1, std::max(a, b));
    }
    double slab = std::max(0.0, t1 - t0);
    // Footprint in the perpendicular plane: y = (t - tClosest) sin(theta), z = 0.
    double yA = (t0 - base.tClosest) * sy, yB = (t1 - base.tClosest) * sy;
    double yMid = 0.5 * (yA + yB), half = 0.5 * std::abs(yB - yA) + 1.2 * r;
    double S = 2 * half, expected = slab / (S * S);
    Rotation rot(rng);
    const int n = 40000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      PairSpec s = base;
      s.shiftY = yMid + half * (2 * rng.nextDouble() - 1);
      s.offset = half * (2 * rng.nextDouble() - 1);
      Pair p = makePair(s, rot);
      RayBeamHit h;
      double k = rayBeamIntersect(p.segment, p.beam, r, h) ? h.kernel : 0.0;
      sum += k, sum2 += k * k;
    }
    double mean = sum / n, sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, expected, 5 * sigma + 1e-4 * expected) << "sigma " << sigma;
  }
}

// --- The OPL interval -----------------------------------------------------

TEST(RayBeam, OplIntervalMatchesTheMarchedExtremes) {
  PCG32 rng(12, 1);
  const float r = 0.1f;
  int checked = 0;
  for (int i = 0; i < 80; ++i) {
    PairSpec s;
    s.theta = DoublePi * rng.nextDouble();
    s.sClosest = 2 * rng.nextDouble(), s.tClosest = 2 * rng.nextDouble();
    s.length = 0.3 + 2 * rng.nextDouble(), s.tMax = 0.3 + 2 * rng.nextDouble();
    s.offset = 0.09 * (2 * rng.nextDouble() - 1);
    s.etaCamera = i % 3 == 0 ? 0.0f : 1.0f + 0.5f * rng.nextFloat();  // observer time off for some
    s.etaBeam = 1.0f + 0.5f * rng.nextFloat();
    Pair p = makePair(s, Rotation(rng), {0, 1, 2});
    test::Overlap ref = marchOverlap(p, r, 100000);
    RayBeamHit h;
    if (!rayBeamIntersect(p.segment, p.beam, r, h) || ref.length < 10 * ref.step) continue;
    ++checked;
    // OPL changes by at most (eta_c + eta_b) per unit t, the gap by at most
    // eta_b: one step each end. The interval is eta_c t + eta_b s(t)'s,
    // shifted by the largest lateral gap (crossed at eta_b).
    double tol = (s.etaCamera + 2 * s.etaBeam) * ref.step + 1e-5;
    EXPECT_NEAR(h.oplBegin, ref.oplMin + s.etaBeam * ref.gapMax, tol) << i;
    EXPECT_NEAR(h.oplEnd, ref.oplMax + s.etaBeam * ref.gapMax, tol) << i;
    // Causal: never before the earliest real path through the overlap.
    EXPECT_GE(h.oplBegin, ref.causalMin - tol) << i;
    // And the rate along the overlap is eta_c + eta_b cos(theta).
    double rate = std::abs(s.etaCamera + s.etaBeam * std::cos(s.theta));
    EXPECT_NEAR(h.oplEnd - h.oplBegin, rate * (h.tRayEnd - h.tRayBegin), 1e-5) << i;
  }
  EXPECT_GT(checked, 20);
}

TEST(RayBeam, AntiParallelIntervalCollapses) {
  PCG32 rng(13, 1);
  const float r = 0.05f;
  for (int i = 0; i < 50; ++i) {
    PairSpec s;
    s.theta = DoublePi, s.sClosest = 1, s.tClosest = 1, s.length = 2, s.tMax = 3;
    s.offset = 0.045 * (2 * rng.nextDouble() - 1);
    s.etaCamera = s.etaBeam = 1.33f;
    Pair p = makePair(s, Rotation(rng), {3, -1, 2});
    RayBeamHit h = mustHit(p, r);
    EXPECT_GT(h.tRayEnd - h.tRayBegin, 1.9);
    // Rounding of the rotated unit vectors leaves |1 + cos| ~ 1e-7.
    EXPECT_LE(h.oplEnd - h.oplBegin, 1e-6) << i;
    // Stationary path length: the light reaching the camera along the beam
    // left the beam's start at OPL 0 and travels ray.o's distance to it.
    // It then crosses the lateral gap |offset| to the camera ray.
    double sAtCamera = 1.0 + 1.0;  // beam start is tClosest + sClosest from the camera
    EXPECT_NEAR(h.oplBegin, 1.33 * (sAtCamera + std::abs(s.offset)), 2e-5) << i;
  }
  // Axis-aligned, exactly anti-parallel: exactly one instant.
  Pair p;
  p.beam.origin = {0, 0.01f, 0}, p.beam.direction = {1, 0, 0}, p.beam.length = 2;
  p.segment.ray = Ray({3, 0, 0}, {-1, 0, 0}), p.segment.tMax = 5;
  RayBeamHit h = mustHit(p, 0.05f);
  EXPECT_EQ(h.oplBegin, h.oplEnd);
  EXPECT_EQ(h.oplBegin, 3.0 + double(0.01f));  // the beam's path to ray.o plus the gap to the ray
  // Different indices: no longer stationary.
  p.segment.eta = 1.5f;
  h = mustHit(p, 0.05f);
  EXPECT_NEAR(h.oplEnd - h.oplBegin, 0.5 * 2.0, 1e-6);
}

TEST(RayBeam, ParallelPairsSpreadWidest) {
  PCG32 rng(14, 1);
  const float r = 0.05f;
  Rotation rot(rng);
  double previousRate = -1;
  // From anti-parallel to parallel the OPL rate per unit camera length grows
  // monotonically from 0 to 2 eta.
  for (double theta = DoublePi; theta >= -1e-9; theta -= DoublePi / 24) {
    PairSpec s;
    s.theta = std::max(theta, 0.0), s.sClosest = 2, s.tClosest = 2, s.length = 4, s.tMax = 4;
    Pair p = makePair(s, rot);
    RayBeamHit h = mustHit(p, r);
    double rate = (h.oplEnd - h.oplBegin) / (h.tRayEnd - h.tRayBegin);
    EXPECT_NEAR(rate, 1 + std::cos(s.theta), 1e-4) << theta;
    EXPECT_GE(rate, previousRate - 1e-6) << theta;
    previousRate = rate;
  }
  EXPECT_NEAR(previousRate, 2.0, 1e-5);
}

// --- Tangent, zero-length and degenerate ---------------------------------

TEST(RayBeam, TangentPassesAreMissesOrFinite) {
  PCG32 rng(15, 1);
  const float r = 0.05f;
  for (double theta : {1e-6, 1e-3, 0.5, 1.5707963, 3.0, DoublePi - 1e-6}) {
    Rotation rot(rng);
    for (int k = -40; k <= 40; ++k) {
      PairSpec s;
      s.theta = theta, s.offset = r * (1 + k * 1e-7), s.sClosest = 1, s.tClosest = 1, s.length = 2, s.tMax = 2;
      Pair p = makePair(s, rot);
      RayBeamHit h;
      if (!rayBeamIntersect(p.segment, p.beam, r, h)) continue;
      EXPECT_TRUE(hitContractHolds(p, h)) << theta << " " << k;
      EXPECT_LE(h.kernel, p.segment.tMax / (DoublePi * r * r) * (1 + 1e-5)) << theta << " " << k;
    }
  }
}

TEST(RayBeam, ZeroLengthOverlapsAreMissesOrFinite) {
  const float r = 0.05f;
  Pair p;
  p.beam.origin = {0, 0, 0}, p.beam.direction = {1, 0, 0}, p.beam.length = 1;
  RayBeamHit h;
  // Perpendicular camera segment lying exactly in the end planes.
  for (float x : {0.0f, 1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(0.0f, -1.0f)}) {
    p.segment.ray = Ray({x, -1, 0}, {0, 1, 0}), p.segment.tMax = 2;
    if (rayBeamIntersect(p.segment, p.beam, r, h)) {
      EXPECT_TRUE(hitContractHolds(p, h)) << x;
    }
  }
  // Segment ending exactly where it enters the cylinder, or starting where it leaves.
  p.segment.ray = Ray({0.5f, -1, 0}, {0, 1, 0}), p.segment.tMax = 1 - r;
  if (rayBeamIntersect(p.segment, p.beam, r, h)) {
    EXPECT_TRUE(hitContractHolds(p, h));
  }
  p.segment.ray = Ray({0.5f, r, 0}, {0, 1, 0}), p.segment.tMax = 1;
  if (rayBeamIntersect(p.segment, p.beam, r, h)) {
    EXPECT_TRUE(hitContractHolds(p, h));
  }
  // Tiny tMax inside the kernel: a tiny but finite chord.
  p.segment.ray = Ray({0.5f, 0, 0}, {0, 1, 0}), p.segment.tMax = 1e-30f;
  ASSERT_TRUE(rayBeamIntersect(p.segment, p.beam, r, h));
  EXPECT_TRUE(hitContractHolds(p, h));
  // Touching a cap edge exactly along the parallel direction.
  p.segment.ray = Ray({1, 0, 0}, {1, 0, 0}), p.segment.tMax = 1;
  if (rayBeamIntersect(p.segment, p.beam, r, h)) {
    EXPECT_TRUE(hitContractHolds(p, h));
  }
}

TEST(RayBeam, DegenerateInputNeverGivesNonFinite) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  Pair good;
  good.beam.origin = {0, 0, 0}, good.beam.direction = {1, 0, 0}, good.beam.length = 1;
  good.segment.ray = Ray({0.5f, -1, 0.01f}, {0, 1, 0}), good.segment.tMax = 2;
  RayBeamHit h;
  ASSERT_TRUE(rayBeamIntersect(good.segment, good.beam, 0.05f, h));
  struct Case {
    const char* name;
    Pair p;
    float r;
  };
  std::vector<Case> cases;
  auto with = [&](const char* name, auto edit, float r = 0.05f) {
    Pair p = good;
    edit(p);
    cases.push_back({name, p, r});
  };
  with("zero-length beam", [](Pair& p) { p.beam.length = 0; });
  with("negative beam length", [](Pair& p) { p.beam.length = -1; });
  with("infinite beam", [&](Pair& p) { p.beam.length = inf; });
  with("NaN beam length", [&](Pair& p) { p.beam.length = nan; });
  with("tMax 0", [](Pair& p) { p.segment.tMax = 0; });
  with("negative tMax", [](Pair& p) { p.segment.tMax = -1; });
  with("NaN tMax", [&](Pair& p) { p.segment.tMax = nan; });
  with("radius 0", [](Pair&) {}, 0.0f);
  with("negative radius", [](Pair&) {}, -0.05f);
  with("radius underflowing when squared", [](Pair&) {}, 1e-30f);
  with("NaN radius", [](Pair&) {}, nan);
  with("infinite radius", [](Pair&) {}, inf);
  with("NaN camera origin", [&](Pair& p) { p.segment.ray.o.x = nan; });
  with("NaN camera direction", [&](Pair& p) { p.segment.ray.d.y = nan; });
  with("zero camera direction", [](Pair& p) { p.segment.ray.d = {0, 0, 0}; });
  with("NaN beam origin", [&](Pair& p) { p.beam.origin.z = nan; });
  with("NaN beam direction", [&](Pair& p) { p.beam.direction = {nan, nan, nan}; });
  with("zero beam direction", [](Pair& p) { p.beam.direction = {0, 0, 0}; });
  with("infinite camera origin", [&](Pair& p) { p.segment.ray.o.y = -inf; });
  with("infinite beam origin", [&](Pair& p) { p.beam.origin.x = inf; });
  with("NaN camera eta", [&](Pair& p) { p.segment.eta = nan; });
  with("infinite beam eta", [&](Pair& p) { p.beam.eta = inf; });
  for (const Case& c : cases) {
    for (RayBeamKernel k : {RayBeamKernel::OneD, RayBeamKernel::Cylinder}) {
      if (rayBeamIntersect(c.p.segment, c.p.beam, c.r, h, k)) {
        EXPECT_TRUE(hitContractHolds(c.p, h)) << c.name;
      }
    }
  }
  // Those that cannot define a kernel region must miss.
  for (const char* name : {"zero-length beam", "tMax 0", "radius 0", "NaN radius", "NaN camera origin",
                           "NaN beam direction", "NaN camera eta"}) {
    for (const Case& c : cases)
      if (std::string(c.name) == name) {
        EXPECT_FALSE(rayBeamIntersect(c.p.segment, c.p.beam, c.r, h)) << name;
      }
  }
  // An unbounded camera segment (medium without a far surface) is fine.
  Pair p = good;
  p.segment.tMax = inf;
  ASSERT_TRUE(rayBeamIntersect(p.segment, p.beam, 0.05f, h));
  EXPECT_NEAR(h.kernel, 1.0 / (2 * 0.05), 1e-3);
}

// Random pairs at many scales, with near-(anti-)parallel ones built on
// purpose: every hit satisfies the contract and the kernel never exceeds
// the chord bound min(tMax, length / |cos|) / (pi r^2).
TEST(RayBeam, FuzzedPairsKeepTheContract) {
  PCG32 rng(16, 1);
  int hits = 0;
  for (int i = 0; i < 100000; ++i) {
    double scale = std::pow(10.0, 6 * rng.nextDouble() - 3);
    PairSpec s;
    double u = rng.nextDouble();
    s.theta = u < 0.25 ? std::pow(10.0, -9 * rng.nextDouble()) : u < 0.5 ? DoublePi - std::pow(10.0, -9 * rng.nextDouble())
                                                                        : DoublePi * rng.nextDouble();
    s.sClosest = scale * (3 * rng.nextDouble() - 1), s.tClosest = scale * (3 * rng.nextDouble() - 1);
    s.length = scale * rng.nextDouble(), s.tMax = scale * 2 * rng.nextDouble();
    float r = float(scale * std::pow(10.0, -3 * rng.nextDouble()));
    s.offset = r * 1.2 * (2 * rng.nextDouble() - 1);
    s.etaCamera = rng.nextFloat() < 0.2f ? 0.0f : 1.0f, s.etaBeam = 1.0f + rng.nextFloat();
    Pair p = makePair(s, Rotation(rng), {scale * rng.nextDouble(), 0, 0});
    for (RayBeamKernel k : {RayBeamKernel::OneD, RayBeamKernel::Cylinder}) {
      RayBeamHit h;
      if (!rayBeamIntersect(p.segment, p.beam, r, h, k)) continue;
      ++hits;
      ASSERT_TRUE(hitContractHolds(p, h)) << i;
      double c = std::abs(dot(p.segment.ray.d, p.beam.direction));
      double bound = std::min(double(p.segment.tMax), p.beam.length / std::max(c, 1e-30)) / (DoublePi * r * r);
      ASSERT_LE(h.kernel, bound * (1 + 1e-3)) << i;
    }
  }
  EXPECT_GT(hits, 20000);
}

}  // namespace
}  // namespace femto::beams
