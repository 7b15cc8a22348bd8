// Russian roulette along photon beams (beam_roulette.h) against closed forms:
// the truncated, reweighted beam integrates any function of the beam
// parameter to the long beam's integral of it times the transmittance, in
// every channel; survival is the empirical probability of reaching s; the
// mean length is (ln(1/Tau) + 1) / sigma. Tolerances: 5 standard errors of
// the sample means (the Monte Carlo estimators' own spread).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <femto/math/pcg32.h>
#include <transient_beams/beam_roulette.h>

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
