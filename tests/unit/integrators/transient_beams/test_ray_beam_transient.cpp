// End to end on the time axis: one beam, a pencil of camera rays crossing it
// at every point along its length and every lateral offset, each ray's
// estimate deposited over its OPL interval with TimeDeposit::interval. The
// reference marches each ray through the beam's kernel region in fine steps
// and bins the blurred beam's density (1/(pi r^2) per unit length) step by
// step: an independent, brute-force time-resolved integral.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <femto/time/time_deposit.h>

#include "ray_beam_test_util.h"

namespace femto::beams {
namespace {

using test::makePair;
using test::Pair;
using test::PairSpec;

constexpr double DoublePi = 3.14159265358979323846;

struct Pencil {
  static constexpr float r = 0.05f;
  static constexpr int alongBeam = 40, acrossBeam = 100;  // crossing points x lateral offsets
  static constexpr double theta = 1.0, tClosest = 2.0;
  /// The ray crossing the beam (length 4, OPL 0 at its start) at sClosest, `offset` from it.
  static Pair ray(int i, int j) {
    PairSpec s;
    s.theta = theta, s.tClosest = tClosest, s.tMax = 4, s.length = 4;
    s.sClosest = 0.5 + 3.0 * (i + 0.5) / alongBeam;  // all crossings well inside the beam
    s.offset = -r + 2 * r * (j + 0.5) / acrossBeam;
    // Identity rotation: the film is axis-free anyway; use a fixed frame.
    static PCG32 rng(21, 1);
    static const test::Rotation rot(rng);
    return makePair(s, rot);
  }
  static int rays() { return alongBeam * acrossBeam; }
};

void accumulate(const BinShares& s, double mass, std::vector<double>& bins) {
  for (size_t k = 0; k < s.weights.size(); ++k) {
    int b = s.first + int(k);
    if (b >= 0 && b < int(bins.size())) bins[size_t(b)] += mass * s.weights[k];
  }
}

/// Pencil average of the estimator's deposits.
std::vector<double> estimate(const TimeDeposit& dep, RayBeamKernel kernel, std::vector<std::pair<double, double>>* ends) {
  std::vector<double> bins(size_t(dep.grid().bins), 0.0);
  BinShares s;
  for (int i = 0; i < Pencil::alongBeam; ++i) {
    for (int j = 0; j < Pencil::acrossBeam; ++j) {
      Pair p = Pencil::ray(i, j);
      RayBeamHit h;
      if (!rayBeamIntersect(p.segment, p.beam, Pencil::r, h, kernel)) continue;
      dep.interval(h.oplBegin, h.oplEnd, s);
      accumulate(s, h.kernel / Pencil::rays(), bins);
      if (ends) ends->push_back({h.oplBegin, h.oplEnd});
    }
  }
  return bins;
}

/// Pencil average of a marched density: each step inside the kernel region
/// carries its mass, spread over the OPLs the step covers (camera OPL + beam
/// OPL: the causal OPL from the beam's start, ray_beam.cpp). `oneD` false: the
/// blurred beam, 1/(pi r^2) per unit length. `oneD` true: the 1D kernel's
/// definition, each pass carrying 1/(2 r sin(theta)) spread evenly over its
/// (marched) chord.
std::vector<double> marchedReference(const TimeDeposit& dep, double step, bool oneD = false) {
  std::vector<double> bins(size_t(dep.grid().bins), 0.0);
  BinShares s;
  const double window = 0.5;  // |t - tClosest| <= r / sin(theta) + margin
  const int steps = int(2 * window / step);
  auto tAt = [&](int k) { return Pencil::tClosest - window + (k + 0.5) * step; };
  for (int i = 0; i < Pencil::alongBeam; ++i) {
    for (int j = 0; j < Pencil::acrossBeam; ++j) {
      Pair p = Pencil::ray(i, j);
      double density = 1.0 / (DoublePi * Pencil::r * Pencil::r);
      if (oneD) {
        int inside = 0;
        for (int k = 0; k < steps; ++k) inside += test::insideKernel(p, Pencil::r, tAt(k));
        if (inside == 0) continue;
        density = 1.0 / (2 * Pencil::r * std::sin(Pencil::theta)) / (inside * step);
      }
      double rate = p.segment.eta + p.beam.eta * dot(p.segment.ray.d, p.beam.direction);
      for (int k = 0; k < steps; ++k) {
        double t = tAt(k), sBeam = 0;
        if (!test::insideKernel(p, Pencil::r, t, &sBeam)) continue;
        (void)sBeam;
        double opl = test::causalOpl(p, t);  // eta = 1 on both
        dep.interval(opl - 0.5 * rate * step, opl + 0.5 * rate * step, s);
        accumulate(s, density * step / Pencil::rays(), bins);
      }
    }
  }
  return bins;
}

/// The causal OPL eta_c t + eta_b |x(t) - b| (ray_beam.cpp) is convex in t;
/// a pair deposits uniformly between its values at the overlap's ends, the
/// straight line above it, at most Curvature above it (|x - b| exceeds the
/// projection s by gap^2 / (2 s) <= r^2 / (2 s), s >= 0.4 on the pencil).
constexpr double Curvature = Pencil::r * Pencil::r / (2 * 0.4);

/// Per-bin tolerance of a march with `step`: at most one step's mass
/// (`endMass`) misplaced at each end of each ray's overlap, in the bins
/// within one step's OPL of that end; and, for the deposit's straight line
/// against the march's convex OPL, each ray's mass (at most `rayMass`) within
/// Curvature of a bin edge inside its interval, a share 2 Curvature / (b - a)
/// per bin it touches.
std::vector<double> marchTolerance(const TimeGrid& g, const std::vector<std::pair<double, double>>& ends,
                                   double step, double endMass, double rayMass) {
  std::vector<double> tol(size_t(g.bins), 1e-9);
  const double slack = 2.0 * step;  // OPL rate <= 2
  for (auto [a, b] : ends) {
    for (double e : {a, b}) {
      int lo = int(std::floor((e - slack - g.start) / g.binWidth));
      int hi = int(std::floor((e + slack - g.start) / g.binWidth));
      for (int k = std::max(lo, 0); k <= std::min(hi, g.bins - 1); ++k) tol[size_t(k)] += endMass;
    }
    int lo = int(std::floor((a - Curvature - g.start) / g.binWidth));
    int hi = int(std::floor((b + Curvature - g.start) / g.binWidth));
    for (int k = std::max(lo, 0); k <= std::min(hi, g.bins - 1); ++k)
      tol[size_t(k)] += rayMass * std::min(1.0, 2 * Curvature / std::max(b - a, 1e-12));
  }
  return tol;
}

TimeGrid grid(double start, double width, int bins) {
  TimeGrid g;
  g.start = start, g.binWidth = width, g.bins = bins;
  return g;
}

// The cylinder kernel is the blurred beam itself: equal bin by bin even with
// bins 9x narrower than one pair's OPL footprint (2r/sin(theta) (1 + cos(theta)) ~ 0.18).
TEST(RayBeamTransient, CylinderKernelIsExactPerBinAtFineBins) {
  TimeDeposit dep(grid(2.0, 0.02, 200), TimeFilter::box());
  std::vector<std::pair<double, double>> ends;
  std::vector<double> est = estimate(dep, RayBeamKernel::Cylinder, &ends);
  const double step = 2e-4;
  std::vector<double> ref = marchedReference(dep, step);
  std::vector<double> tol =
      marchTolerance(dep.grid(), ends, step, step / (DoublePi * Pencil::r * Pencil::r) / Pencil::rays(),
                     2 * Pencil::r / std::sin(Pencil::theta) / (DoublePi * Pencil::r * Pencil::r) / Pencil::rays());
  double total = 0, totalRef = 0;
  int nonEmpty = 0;
  for (size_t k = 0; k < est.size(); ++k) {
    EXPECT_NEAR(est[k], ref[k], tol[k]) << "bin " << k;
    total += est[k], totalRef += ref[k];
    nonEmpty += ref[k] > 0;
  }
  EXPECT_GT(nonEmpty, 150);  // the pencil covers OPL 2.5 .. 5.5
  EXPECT_NEAR(total, totalRef, 1e-3 * totalRef);
}

// Each 1D pass spreads 1/(2 r sin(theta)) over its own chord's OPLs: equal to
// the marched definition bin by bin at fine bins.
TEST(RayBeamTransient, OneDKernelSpreadsEachPassOverItsChord) {
  TimeDeposit dep(grid(2.0, 0.02, 200), TimeFilter::box());
  std::vector<std::pair<double, double>> ends;
  std::vector<double> est = estimate(dep, RayBeamKernel::OneD, &ends);
  const double step = 2e-4;
  std::vector<double> ref = marchedReference(dep, step, true);
  // The shortest chords (|d| near r) have the densest mass per step: bound
  // one misplaced step each end by the 1D mass over the shortest marched chord (>= 4 steps).
  double kernel1D = 1.0 / (2 * Pencil::r * std::sin(Pencil::theta));
  double minChord = 1e30;
  for (auto [a, b] : ends) minChord = std::min(minChord, (b - a) / (1 + std::cos(Pencil::theta)));
  minChord = std::max(minChord, 4 * step);
  std::vector<double> tol =
      marchTolerance(dep.grid(), ends, step, kernel1D * 2 * step / minChord / Pencil::rays(), kernel1D / Pencil::rays());
  double total = 0, totalRef = 0;
  for (size_t k = 0; k < est.size(); ++k) {
    // Inside a chord the marched density is off by (marched/true chord - 1) <= 2 steps / chord.
    EXPECT_NEAR(est[k], ref[k], tol[k] + ref[k] * 2 * step / minChord) << "bin " << k;
    total += est[k], totalRef += ref[k];
  }
  EXPECT_NEAR(total, totalRef, 1e-6 * totalRef);
}

// The 1D kernel weighs every pass of a pair equally instead of by its chord:
// its time profile is the blurred beam's smoothed within one footprint, and
// equal to it in any bin that holds whole pairs. With bins wider than the
// footprint the difference is confined to pairs straddling a bin edge.
TEST(RayBeamTransient, OneDKernelMatchesTheBlurredBeamAcrossBins) {
  const double width = 0.5;
  TimeDeposit dep(grid(2.0, width, 8), TimeFilter::box());
  std::vector<double> est = estimate(dep, RayBeamKernel::OneD, nullptr);
  std::vector<double> ref = marchedReference(dep, 2e-4);
  // Per pair (fixed crossing point, all offsets): if its OPL footprint
  // straddles an edge, the two kernels may distribute its mass differently
  // between the two bins -- up to the pair's whole mass.
  std::vector<double> tol(est.size(), 0.0);
  double total = 0, totalRef = 0;
  for (int i = 0; i < Pencil::alongBeam; ++i) {
    double lo = 1e30, hi = -1e30, mass = 0;
    for (int j = 0; j < Pencil::acrossBeam; ++j) {
      Pair p = Pencil::ray(i, j);
      RayBeamHit h;
      if (!rayBeamIntersect(p.segment, p.beam, Pencil::r, h)) continue;
      lo = std::min(lo, h.oplBegin), hi = std::max(hi, h.oplEnd);
      mass += h.kernel / Pencil::rays();
    }
    int a = int(std::floor((lo - 2.0) / width)), b = int(std::floor((hi - 2.0) / width));
    if (a != b) {
      for (int k = std::max(a, 0); k <= std::min(b, 7); ++k) tol[size_t(k)] += mass;
    }
  }
  for (size_t k = 0; k < est.size(); ++k) {
    // Pairs inside one bin: equal up to the midpoint rule over the offsets
    // (the chord's sqrt edge, ~ acrossBeam^-1.5) and the march (~1e-3).
    EXPECT_NEAR(est[k], ref[k], tol[k] + 3e-3 * ref[k] + 1e-9) << "bin " << k;
    total += est[k], totalRef += ref[k];
  }
  EXPECT_NEAR(total, totalRef, 3e-3 * totalRef);
}

}  // namespace
}  // namespace femto::beams

namespace femto::beams {

// Without observer time a pair's OPL along the camera segment, eta_b |x(t) - b|,
// is stationary where the ray passes closest to the beam's start b: the
// deposit's density is the push-forward of uniform t through that hyperbola,
// with an integrable peak at its minimum. PairOpl::pieces' chords must match
// the exact push-forward's CDF (|{t in overlap : g(t) <= tau}| / overlap)
// within the tolerance asked for, at every tau; the overlap's two end values
// alone (one uniform deposit) miss every arrival before the earlier end.
TEST(RayBeamTransient, PiecesFollowTheStationaryOplWithoutObserverTime) {
  Beam beam;
  beam.origin = Point3f(0.0f, 0.3f, 0.0f);  // 0.3 from the camera ray's line (the x axis)
  beam.direction = normalize(Vec3f(0.05f, -1.0f, 0.0f));
  beam.length = 2.0f, beam.eta = 1.33f;
  CameraSegment seg;
  seg.ray = Ray(Point3f(-1.0f, 0.0f, 0.0f), Vec3f(1.0f, 0.0f, 0.0f));
  seg.tMax = 3.0f, seg.eta = 0.0f;  // observer time off
  const float radius = 0.2f;
  RayBeamHit hit;
  ASSERT_TRUE(rayBeamIntersect(seg, beam, radius, hit, RayBeamKernel::Cylinder));
  const double a = hit.tRayBegin, b = hit.tRayEnd, tStar = 1.0;  // closest to the start at x = 0
  ASSERT_LT(a, tStar);
  ASSERT_GT(b, tStar);
  const PairOpl g(seg, beam, radius, hit);
  const double h = 0.3, eta = 1.33;
  auto exactCdf = [&](double tau) {  // |{t in [a, b] : eta sqrt(h^2 + (t - t*)^2) <= tau}| / (b - a)
    if (tau <= eta * h) return 0.0;
    const double u = std::sqrt(std::pow(tau / eta, 2) - h * h);
    return std::max(0.0, std::min(b, tStar + u) - std::max(a, tStar - u)) / (b - a);
  };
  const double tolerance = 0.002;
  PairOpl::Piece pieces[64];
  const int n = g.pieces(tolerance, pieces, 64);
  ASSERT_GE(n, 2) << "split at the stationary point";
  double weights = 0.0;
  for (int i = 0; i < n; ++i) {
    weights += pieces[i].weight;
    EXPECT_GE(pieces[i].begin, eta * h - 1e-6) << "before the earliest arrival";
  }
  EXPECT_NEAR(weights, 1.0, 1e-9);
  auto pieceCdf = [&](double tau) {
    double c = 0.0;
    for (int i = 0; i < n; ++i) {
      const PairOpl::Piece& p = pieces[i];
      const double f = p.end > p.begin ? std::clamp((tau - p.begin) / (p.end - p.begin), 0.0, 1.0) : tau >= p.begin;
      c += p.weight * f;
    }
    return c;
  };
  // Each chord lies within `tolerance` above the OPL it stands for, so the
  // pieces' CDF at tau is between the exact CDF at tau - tolerance and at tau.
  const double lo = eta * h, hi = std::max(g(float(a)), g(float(b)));
  double worstUniform = 0.0;
  for (int k = 0; k <= 2000; ++k) {
    const double tau = lo + (hi - lo) * k / 2000.0;
    EXPECT_LE(pieceCdf(tau), exactCdf(tau) + 1e-6) << tau;
    EXPECT_GE(pieceCdf(tau), exactCdf(tau - tolerance) - 1e-6) << tau;
    const double uniform = std::clamp((tau - hit.oplBegin) / (hit.oplEnd - hit.oplBegin), 0.0, 1.0);
    worstUniform = std::max(worstUniform, std::abs(uniform - exactCdf(tau)));
  }
  // The single deposit between the ends' values is off by a fifth of the mass or more here.
  EXPECT_GT(worstUniform, 0.2);
}

}  // namespace femto::beams
