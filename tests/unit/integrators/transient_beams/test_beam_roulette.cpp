// Russian roulette along photon beams (beam_roulette.h) against closed forms:
// the truncated, reweighted beam integrates any function of the beam
// parameter to the long beam's integral of it times the transmittance, in
// every channel; survival is the empirical probability of reaching s; the
// mean length is (ln(1/Tau) + 1) / sigma; a camera segment's gather ended by
// the roulette still gathers the blurred beam's exact value. Tolerances: 5
// standard errors of the sample means (the Monte Carlo estimators' own
// spread), plus a derived bound where the estimate evaluates at a point.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <femto/math/pcg32.h>
#include <transient_beams/beam_roulette.h>
#include <transient_beams/ray_beam.h>

namespace femto::beams {
namespace {

struct Mean {
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  void add(double x) { sum += x, sum2 += x * x, ++n; }
  double mean() const { return sum / n; }
  double standardError() const { return std::sqrt(std::max(0.0, sum2 / n - mean() * mean()) / n); }
};

/// Simpson's rule for f over [a, b] (a <= b), 64 intervals.
template <typename F>
double simpson(F f, double a, double b) {
  if (!(b > a)) return 0.0;
  const int n = 64;
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * h);
  return sum * h / 3.0;
}

/// The truncated beam's estimate of int_0^L g(s) T(s) ds for one roulette
/// draw: int_0^min(L, lambda) g(s) T(s) / S(s) ds by Simpson's rule, split
/// where the roulette starts (s0 = ln(1/Tau) / sigma, where 1 / S has a
/// kink), so its error is far below the tolerance.
template <typename G>
double truncatedIntegral(const BeamRoulette& roulette, float sigma, float lambda, float length, float sigmaT, G g) {
  const double end = std::min(double(length), double(lambda));
  const double s0 = std::min(end, std::log(1.0 / double(BeamRoulette::Tau)) / sigma);
  auto f = [&](double s) { return g(s) * std::exp(-double(sigmaT) * s) * roulette.inverseSurvival(float(s)); };
  return simpson(f, 0.0, s0) + simpson(f, s0, end);
}

TEST(BeamRoulette, TruncatedBeamsIntegrateToTheLongBeamInEveryChannel) {
  // The roulette's rate is the smallest extinction; the other channels fall
  // faster. A beam of 12 mean free paths (of the slowest channel).
  const float sigma = 0.5f, length = 24.0f;
  const float channels[] = {0.5f, 1.0f, 2.0f};
  const BeamRoulette roulette(sigma);
  PCG32 rng(7, 3);
  const int samples = 16000;
  for (float sigmaT : channels) {
    Mean flat, linear;
    for (int i = 0; i < samples; ++i) {
      const float lambda = roulette.sampleLength(rng.nextFloat());
      flat.add(truncatedIntegral(roulette, sigma, lambda, length, sigmaT, [](double) { return 1.0; }));
      linear.add(truncatedIntegral(roulette, sigma, lambda, length, sigmaT, [](double s) { return s; }));
    }
    // int_0^L e^{-k s} ds and int_0^L s e^{-k s} ds.
    const double k = sigmaT, eL = std::exp(-k * length);
    const double flatExact = (1.0 - eL) / k;
    const double linearExact = (1.0 - eL * (1.0 + k * length)) / (k * k);
    EXPECT_NEAR(flat.mean(), flatExact, 5.0 * flat.standardError()) << "sigma_t " << sigmaT;
    EXPECT_NEAR(linear.mean(), linearExact, 5.0 * linear.standardError()) << "sigma_t " << sigmaT;
    // The truncation must actually happen for the test to mean anything.
    EXPECT_GT(flat.standardError(), 0.0);
  }
}

TEST(BeamRoulette, SurvivalIsTheProbabilityOfReachingAPoint) {
  const float sigma = 2.0f;
  const BeamRoulette roulette(sigma);
  const float s0 = std::log(1.0f / BeamRoulette::Tau) / sigma;
  const std::vector<float> points = {0.1f * s0, s0, s0 + 0.5f / sigma, s0 + 2.0f / sigma};
  std::vector<int> reached(points.size(), 0);
  PCG32 rng(11, 5);
  const int samples = 20000;
  Mean length;
  for (int i = 0; i < samples; ++i) {
    const float lambda = roulette.sampleLength(rng.nextFloat());
    length.add(lambda);
    for (size_t k = 0; k < points.size(); ++k) reached[k] += lambda > points[k];
  }
  for (size_t k = 0; k < points.size(); ++k) {
    // S(s) = min(1, e^{-sigma s} / Tau), in closed form.
    const double exact = std::min(1.0, std::exp(-double(sigma) * points[k]) / double(BeamRoulette::Tau));
    EXPECT_NEAR(roulette.survival(points[k]), exact, 1e-5);
    EXPECT_NEAR(roulette.inverseSurvival(points[k]) * exact, 1.0, 1e-5);
    const double p = double(reached[k]) / samples;
    EXPECT_NEAR(p, exact, 5.0 * std::sqrt(exact * (1.0 - exact) / samples) + 1e-12) << "s = " << points[k];
  }
  // E[lambda] = s0 + 1 / sigma.
  EXPECT_NEAR(length.mean(), (std::log(1.0 / BeamRoulette::Tau) + 1.0) / sigma, 5.0 * length.standardError());
}

/// One camera gather along +x from the origin, ended by the roulette at
/// `lambda`, of a long beam crossing the x axis at `crossing` (angle `theta`
/// to it) with offset `offset` along z (the lines' distance): the pair's
/// kernel times T_cam(tRay) / S(tRay), as gatherBeams weighs it.
double gatherOnce(const BeamRoulette& roulette, float sigma, float lambda, float crossing, float theta, float offset,
                  float radius, float tMax) {
  CameraSegment segment;
  segment.ray = Ray(Point3f(0.0f), Vec3f(1.0f, 0.0f, 0.0f));
  segment.tMax = std::min(tMax, lambda);
  Beam beam;
  beam.direction = Vec3f(std::cos(theta), std::sin(theta), 0.0f);
  const float half = 50.0f;  // long: its ends never reach the kernel
  beam.origin = Point3f(crossing, 0.0f, offset) - beam.direction * half;
  beam.length = 2.0f * half;
  RayBeamHit hit;
  if (!rayBeamIntersect(segment, beam, radius, hit)) return 0.0;
  return double(hit.kernel) * std::exp(-double(sigma) * hit.tRay) * roulette.inverseSurvival(hit.tRay);
}

TEST(BeamRoulette, AGatherEndedByTheRouletteKeepsTheBlurredBeam) {
  // The blurred beam's value for one pass at offset d: the chord of the
  // kernel cylinder, t_c +- h(d), h(d) = sqrt(r^2 - d^2) / sin(theta),
  // integrated against T_cam = e^{-sigma t} over the disc's area pi r^2;
  // averaged over offsets uniform in [-D, D] (the 1D kernel is unbiased on
  // that average, docs/design/photon-beams.md "Kernel value"). Crossings before,
  // at and past s0 = ln(1 / GatherTau) / sigma, where the gather's roulette
  // starts.
  const float sigma = 1.0f, radius = 0.002f, tMax = 20.0f, spread = 1.5f * radius;
  const BeamRoulette roulette(sigma, BeamRoulette::GatherTau);
  const float s0 = std::log(1.0f / BeamRoulette::GatherTau) / sigma;
  struct Crossing {
    float at, theta;
  };
  const Crossing crossings[] = {{0.5f * s0, 1.0f}, {s0, 1.0f}, {s0 + 1.5f / sigma, 1.0f}, {s0 + 3.0f / sigma, 0.35f}};
  PCG32 rng(23, 9);
  const int samples = 400000;
  for (const Crossing& c : crossings) {
    Mean gathered;
    int ended = 0;
    for (int i = 0; i < samples; ++i) {
      const float offset = spread * (2.0f * rng.nextFloat() - 1.0f);
      const float lambda = roulette.sampleLength(rng.nextFloat());
      ended += lambda < c.at;
      gathered.add(gatherOnce(roulette, sigma, lambda, c.at, c.theta, offset, radius, tMax));
    }
    const double sinT = std::sin(double(c.theta)), r = radius;
    auto blurred = [&](double d) {
      const double h = std::sqrt(std::max(0.0, r * r - d * d)) / sinT;
      return (std::exp(-sigma * (c.at - h)) - std::exp(-sigma * (c.at + h))) / (sigma * Pi * r * r);
    };
    const double exact = simpson(blurred, -r, r) / (2.0 * spread);
    // The 1D kernel evaluates T_cam / S at one point of a chord of half
    // length h <= r / sin(theta): T / S changes by at most a factor
    // e^{sigma h} across it (also where S has its kink, at s0).
    const double pointBound = std::expm1(sigma * r / sinT) * exact;
    EXPECT_NEAR(gathered.mean(), exact, 5.0 * gathered.standardError() + pointBound) << "crossing at " << c.at;
    if (c.at > s0) EXPECT_GT(ended, samples / 20) << "the roulette must end some gathers before the beam";
  }
}

TEST(BeamRoulette, InactiveRouletteNeverTruncates) {
  for (float sigma : {0.0f, -1.0f, Infinity, std::nanf("")}) {
    const BeamRoulette roulette(sigma);
    EXPECT_FALSE(roulette.active());
    EXPECT_EQ(roulette.sampleLength(0.5f), Infinity);
    EXPECT_EQ(roulette.survival(1e6f), 1.0f);
    EXPECT_EQ(roulette.inverseSurvival(1e6f), 1.0f);
  }
  // u at the top of [0, 1) still gives a finite length.
  EXPECT_TRUE(std::isfinite(BeamRoulette(1.0f).sampleLength(0x1.fffffep-1f)));
  EXPECT_TRUE(std::isfinite(BeamRoulette(1.0f).sampleLength(1.0f)));
}

}  // namespace
}  // namespace femto::beams
