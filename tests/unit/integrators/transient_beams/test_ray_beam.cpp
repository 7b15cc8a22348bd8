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

#include <transient_beams/boundary_extension.h>

namespace femto::beams {
namespace {

using test::dotD;
using test::hitContractHolds;
using test::makePair;
using test::marchOverlap;
using test::Pair;
using test::PairSpec;
using test::Rotation;
using test::toD;
using test::Vec3d;

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
    // OPL changes by at most (eta_c + eta_b) per unit t: one step each end.
    // The interval runs between the causal OPL's values at the overlap's
    // ends, which is never below its minimum (causality).
    double tol = (s.etaCamera + s.etaBeam) * ref.step + 1e-5;
    EXPECT_NEAR(h.oplBegin, std::min(ref.causalFirst, ref.causalLast), tol) << i;
    EXPECT_NEAR(h.oplEnd, std::max(ref.causalFirst, ref.causalLast), tol) << i;
    EXPECT_GE(h.oplBegin, ref.causalMin - tol) << i;
    // Away from the beam's start that is the projection's OPL, eta_c t + eta_b s(t),
    // up to eta_b gap^2 / (2 s) <= eta_b r^2 / (2 s).
    if (s.sClosest > 0.5 && s.sClosest + 0.5 < s.length) {
      EXPECT_NEAR(h.oplBegin, ref.oplMin, tol + s.etaBeam * r * r / 0.1) << i;
      EXPECT_NEAR(h.oplEnd, ref.oplMax, tol + s.etaBeam * r * r / 0.1) << i;
    }
  }
  EXPECT_GT(checked, 20);
}

TEST(RayBeam, AntiParallelIntervalCollapsesToTheLateralGap) {
  // The beam's light travels toward the camera along the ray: the path
  // length along the beam and back along the ray is stationary, and what is
  // left of the interval is the lateral gap d: light leaving the beam's far
  // end (s = 2) reaches the ray after sqrt(2^2 + d^2), light from its start
  // after d, so the interval is eta [sqrt(4 + d^2), 2 + d] (width ~ eta d <= eta r).
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
    const double d = std::abs(s.offset);
    // Rounding of the rotated unit vectors leaves |1 + cos| ~ 1e-7.
    EXPECT_NEAR(h.oplBegin, 1.33 * std::sqrt(4.0 + d * d), 2e-5) << i;
    EXPECT_NEAR(h.oplEnd, 1.33 * (2.0 + d), 2e-5) << i;
    EXPECT_LE(h.oplEnd - h.oplBegin, 1.33 * r) << i;
  }
  // Axis-aligned, exactly anti-parallel, gap 0.01.
  Pair p;
  p.beam.origin = {0, 0.01f, 0}, p.beam.direction = {1, 0, 0}, p.beam.length = 2;
  p.segment.ray = Ray({3, 0, 0}, {-1, 0, 0}), p.segment.tMax = 5;
  RayBeamHit h = mustHit(p, 0.05f);
  const double gap = double(0.01f);
  EXPECT_NEAR(h.oplBegin, 1.0 + std::sqrt(4.0 + gap * gap), 1e-9);
  EXPECT_NEAR(h.oplEnd, 3.0 + gap, 1e-9);
  // Different indices: no longer stationary, the camera part grows by 0.5 per unit.
  p.segment.eta = 1.5f;
  h = mustHit(p, 0.05f);
  EXPECT_NEAR(h.oplEnd - h.oplBegin, (4.5 + gap) - (1.5 + std::sqrt(4.0 + gap * gap)), 1e-6);
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
    double chord = h.tRayEnd - h.tRayBegin;
    double rate = (h.oplEnd - h.oplBegin) / chord;
    // The causal OPL's ends differ from the projection's by gap^2 / (2 s)
    // <= r^2 / 2 each (s >= 1 at the overlap's ends here, gap <= r).
    EXPECT_NEAR(rate, 1 + std::cos(s.theta), 1e-4 + r * r / chord) << theta;
    EXPECT_GE(rate, previousRate - 1e-6) << theta;
    previousRate = rate;
  }
  EXPECT_NEAR(previousRate, 2.0, 1e-5);
}

// A beam extended before its start (boundary_extension.h: before = 8, a
// beam entering its medium at 7 degrees from the boundary) is timed as its
// own continuation: a camera segment crossing it perpendicularly at beam
// parameter s (s < 0 on the extension) deposits around eta_c t_c + eta_b s,
// measured from the extension's start b - e v at the OPL -eta_b e (up to the
// lateral path eta_b gap^2 / (2 (s + e)), at most eta_b r at s = -e). Timed
// from b (the code before issue 14's oblique step) the extension arrived
// 2 eta_b |s| late: up to 32 eta_b r behind the real beams it stands for.
TEST(RayBeam, ExtensionBeforeTheStartIsTimedAsTheBeamsContinuation) {
  const float r = 0.05f, etaB = 1.3f, etaC = 1.2f;
  Beam beam;
  beam.origin = Point3f(0.0f), beam.direction = Vec3f(0.0f, 0.0f, 1.0f), beam.length = 1.0f, beam.eta = etaB;
  beam.before = 8.0f;
  const double e = beam.before * r;
  int crossings = 0;
  for (double s = -e + 0.25 * r; s <= 2.0 * r; s += 0.25 * r) {
    CameraSegment seg;
    seg.ray = Ray(Point3f(-1.0f, 0.3f * r, float(s)), Vec3f(1.0f, 0.0f, 0.0f));
    seg.tMax = 2.0f, seg.eta = etaC;
    RayBeamHit h;
    ASSERT_TRUE(rayBeamIntersect(seg, beam, r, h)) << s;
    ++crossings;
    const double middle = 0.5 * (h.oplBegin + h.oplEnd), continuation = etaC * 1.0 + etaB * s;
    const double lateral = etaB * std::min(double(r), double(r) * r / (2.0 * (s + e)));
    EXPECT_NEAR(middle, continuation, lateral + 1e-4) << "s = " << s;
    EXPECT_LE(h.oplEnd - h.oplBegin, 2.0 * etaC * r + lateral + 1e-4) << "perpendicular: a chord of 2 r at most";
  }
  EXPECT_GE(crossings, 36);
}

// A beam that entered through a pass-through plane where the index rose
// from 1 to eta_b (offsetDelay, boundary_extension.h): pairs on its
// extension are timed no earlier than the plane wave that crossed the plane
// beside the start, s(x) + (eta_b - 1) lambda(x) at camera point x, and no
// earlier than the continuation with its lateral path (ray_beam.cpp: the
// later of the two, at the overlap's ends); the continuation alone at eta_b
// is (eta_b - 1)(lambda - s) earlier than the wave here, and the test sees
// it.
TEST(RayBeam, ExtensionAfterAnIndexChangeIsTimedAsThePlaneWave) {
  const float r = 0.05f, etaB = 1.45f, etaC = 1.0f;
  const Vec3f n = normalize(Vec3f(0.9f, 0.0f, 0.3f));  // the boundary through b = 0, grazing entry
  Beam beam;
  beam.origin = Point3f(0.0f), beam.direction = Vec3f(0.0f, 0.0f, 1.0f), beam.length = 1.0f, beam.eta = etaB;
  beam.before = boundaryExtension(n, beam.direction);
  beam.offsetDelay = boundaryOffsetDelay(n, beam.direction, etaB - 1.0f);
  auto wave = [&](const Point3f& x) {
    const double lambda = double(dot(n, x - beam.origin)) / double(dot(n, beam.direction));
    return double(x.z) + (etaB - 1.0) * lambda;
  };
  int onExtension = 0;
  for (double s = -beam.before * r + 0.1 * r; s < 0.0; s += 0.1 * r)
    for (double y : {-0.5, 0.0, 0.5}) {
      // Camera segments along -x at height s, inside the medium (n.x > 0) where they cross the beam.
      CameraSegment seg;
      seg.ray = Ray(Point3f(1.0f, float(y * r), float(s)), Vec3f(-1.0f, 0.0f, 0.0f));
      seg.tMax = 2.0f, seg.eta = etaC;
      RayBeamHit h;
      if (!rayBeamIntersect(seg, beam, r, h)) continue;
      // The overlap reaches into the medium (n.x > 0) where camera segments gather.
      if (!(dot(n, seg.ray(h.tRayBegin)) > 0.0f)) continue;
      ++onExtension;
      const double e = beam.before * r;
      auto expected = [&](float t) {
        const Point3f x = seg.ray(t);
        const double continuation = -etaB * e + etaB * double(length(x - (beam.origin - beam.direction * float(e))));
        return etaC * t + std::max(wave(x), continuation);
      };
      const double a = expected(h.tRayBegin), b = expected(h.tRayEnd);
      EXPECT_NEAR(h.oplBegin, std::min(a, b), 1e-4) << "s = " << s;
      EXPECT_NEAR(h.oplEnd, std::max(a, b), 1e-4) << "s = " << s;
      EXPECT_GE(h.oplBegin,
                std::min(etaC * h.tRayBegin + wave(seg.ray(h.tRayBegin)), etaC * h.tRayEnd + wave(seg.ray(h.tRayEnd))) -
                    1e-4);
      const double continuation = etaC * h.tRay + etaB * s;
      EXPECT_GT(0.5 * (h.oplBegin + h.oplEnd), continuation) << "the continuation at eta_b is early here";
    }
  EXPECT_GE(onExtension, 20);
}

// --- Causality -------------------------------------------------------------

/// Smallest distance from `q` to the points ray.o + t ray.d, t in [t0, t1].
double distanceToPiece(const CameraSegment& seg, double t0, double t1, const Point3f& q) {
  Vec3d o = toD(seg.ray.o), d = toD(seg.ray.d), rel = toD(q) - o;
  double t = std::clamp(dotD(rel, d), t0, t1);
  Vec3d gap = rel - d * t;
  return std::sqrt(dotD(gap, gap));
}

// No estimate arrives before light could: a beam leaving its start b at OPL
// 0, light reaching camera point x(t) no earlier than eta |x(t) - b|, so
// with observer time the camera at ray.o no earlier than eta |ray.o - b|
// (the light cone of b), and without it (eta_c = 0) no pair before
// eta min |x(t) - b| over its overlap. Hard cases, 20000 pairs each: the
// camera ray grazing the kernel cylinder (|offset| -> r), parallel and
// anti-parallel to the beam, and the kernel straddling the light cone (the
// crossing within a few radii of the beam's start, the camera ray starting
// inside the kernel beside it). Without the lateral path (the projection's
// OPL eta_c t + eta_b s(t), the estimate before issue 14) the same pairs
// arrive early: the test sees it.
TEST(RayBeam, NoEstimateArrivesBeforeLightCould) {
  PCG32 rng(31, 7);
  const float r = 0.05f;
  enum Case { Grazing, Parallel, AntiParallel, Straddling, Cases };
  for (int c = 0; c < Cases; ++c) {
    int hits = 0, earlyWithoutLateralPath = 0;
    for (int i = 0; i < 20000; ++i) {
      PairSpec s;
      s.length = 0.2 + 2 * rng.nextDouble();
      s.tMax = 0.2 + 3 * rng.nextDouble();
      s.theta = DoublePi * rng.nextDouble();
      s.sClosest = s.length * rng.nextDouble();
      s.tClosest = s.tMax * rng.nextDouble();
      s.offset = r * (2 * rng.nextDouble() - 1);
      if (c == Grazing) s.offset = r * (1 - 1e-3 * rng.nextDouble()) * (rng.nextDouble() < 0.5 ? -1 : 1);
      if (c == Parallel) s.theta = 1e-4 * rng.nextDouble();
      if (c == AntiParallel) s.theta = DoublePi - 1e-4 * rng.nextDouble();
      if (c == Straddling) s.sClosest = 3 * r * rng.nextDouble(), s.tClosest = 3 * r * rng.nextDouble();
      const bool observerTime = i % 2 == 0;
      const float eta = 1.0f + 0.5f * rng.nextFloat();
      s.etaBeam = eta, s.etaCamera = observerTime ? eta : 0.0f;
      Pair p = makePair(s, Rotation(rng), {float(rng.nextDouble()), 1, -2});
      RayBeamHit h;
      if (!rayBeamIntersect(p.segment, p.beam, r, h)) continue;
      ++hits;
      const double bound = observerTime ? eta * distance(p.segment.ray.o, p.beam.origin)
                                        : eta * distanceToPiece(p.segment, h.tRayBegin, h.tRayEnd, p.beam.origin);
      const double tol = 1e-5 * (1 + bound);
      EXPECT_GE(h.oplBegin, bound - tol) << "case " << c << " pair " << i;
      // The projection's OPL at the overlap's ends.
      double projection = 1e30;
      for (double t : {double(h.tRayBegin), double(h.tRayEnd)}) {
        Vec3d x = toD(p.segment.ray.o) + toD(p.segment.ray.d) * t;
        projection =
            std::min(projection, double(p.segment.eta) * t +
                                     double(eta) * std::clamp(dotD(x - toD(p.beam.origin), toD(p.beam.direction)), 0.0,
                                                              double(p.beam.length)));
      }
      earlyWithoutLateralPath += projection < bound - tol;
    }
    std::printf("case %d: %d hits, %d would arrive early without the lateral path\n", c, hits, earlyWithoutLateralPath);
    EXPECT_GT(hits, 1000) << "case " << c;
    EXPECT_GT(earlyWithoutLateralPath, 0) << "case " << c << ": the check could not fail";
  }
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
  with(
      "radius 0", [](Pair&) {}, 0.0f);
  with(
      "negative radius", [](Pair&) {}, -0.05f);
  with(
      "radius underflowing when squared", [](Pair&) {}, 1e-30f);
  with(
      "NaN radius", [](Pair&) {}, nan);
  with(
      "infinite radius", [](Pair&) {}, inf);
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
    s.theta = u < 0.25  ? std::pow(10.0, -9 * rng.nextDouble())
              : u < 0.5 ? DoublePi - std::pow(10.0, -9 * rng.nextDouble())
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
